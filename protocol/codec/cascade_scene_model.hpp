// The scene model's view of one cascade (common/cascade.hpp), derived by the rule of the sim's
// cascade_scene: the scene's weather on the cascade's lattice, band and seed, with the scene's
// suppression length. CODEC.md 7.7 states the rule for other implementations.
#pragma once

#include "common/cascade.hpp"
#include "scene_model_params.hpp"

namespace ocean::codec {

// Throws std::invalid_argument when the cascade or the scene it makes is unusable.
SceneModelParams cascade_scene_model(const SceneModelParams& scene, const Cascade& cascade, int index);

}  // namespace ocean::codec
