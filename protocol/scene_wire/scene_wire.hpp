// The scene's enums as the schema names them (ParamChange.spectrum), both directions. The
// messages carry the scene itself (protocol::SceneParams is model::SceneParams; the builders and
// readers write the wire's conventions), and this file's static_asserts hold the model's enums
// and the schema's to the same numbers.
#pragma once

#include "message_types.hpp"
#include "scene_params.hpp"

namespace ocean::scene_wire {

wire::Spectrum to_wire(model::SpectrumKind kind);
wire::Spreading to_wire(model::SpreadingKind kind);
model::SpectrumKind to_scene(wire::Spectrum spectrum);
model::SpreadingKind to_scene(wire::Spreading spreading);

}  // namespace ocean::scene_wire
