// The scene (model::SceneParams) as the wire carries it (Welcome, SceneUpdate, ParamChange), both
// directions, in one place: the server, every client's scene model, the load test and ocean-admin
// go through it. The two differ in deep water (model/scene_params.hpp: infinity in a scene, 0 on
// the wire) and in the enums' types.
#pragma once

#include "message_types.hpp"
#include "scene_params.hpp"

namespace ocean::scene_wire {

wire::Spectrum to_wire(model::SpectrumKind kind);
wire::Spreading to_wire(model::SpreadingKind kind);
model::SpectrumKind to_scene(wire::Spectrum spectrum);
model::SpreadingKind to_scene(wire::Spreading spreading);

protocol::SceneParams to_wire(const model::SceneParams& scene);
// Not validated: a scene off the wire goes through model::validate (or what builds on it) next.
model::SceneParams to_scene(const protocol::SceneParams& scene);

}  // namespace ocean::scene_wire
