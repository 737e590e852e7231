// The scene one cascade realizes (common/cascade.hpp): the scene's weather on the cascade's own
// lattice, band and seed, with the scene's suppression length so that every cascade filters the
// small waves alike. The sim's Ocean and the codec's scene model of a cascade are built from it
// (CODEC.md 7.7 states the rule for other implementations).
#pragma once

#include "common/cascade.hpp"
#include "scene_params.hpp"

namespace ocean::model {

// Throws ParamError when the cascade or the scene it makes is unusable.
SceneParams cascade_scene(const SceneParams& scene, const Cascade& cascade, int index);

}  // namespace ocean::model
