// The scene one cascade realizes (common/cascade.hpp): the scene's weather on the cascade's own
// lattice, band and seed, with the scene's suppression length so that every cascade filters the
// small waves alike. An Ocean built from it evaluates that cascade.
#pragma once

#include "common/cascade.hpp"
#include "frame.hpp"
#include "scene_params.hpp"

namespace ocean::sim {

// Throws ParamError when the cascade or the scene it makes is unusable.
SceneParams cascade_scene(const SceneParams& scene, const Cascade& cascade, int index);

// Appends the fields of one cascade's frame to `out`'s: a cascaded stream's frame holds its
// cascades' samples one after the other, field by field (the codec's StreamConfig::cascades).
void append_cascade_frame(Frame& out, const Frame& part);

}  // namespace ocean::sim
