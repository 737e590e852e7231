// The scene as the sim holds it and as the wire carries it (Welcome, SceneUpdate, ParamChange).
// The two differ in one rule, deep water: infinity in the sim, 0 on the wire. That rule and the
// enum mapping live here and nowhere else; the server, the load test and ocean-admin go through it.
// (Wire -> codec is protocol/codec/stream_wire.hpp: the codec may not depend on the sim.)
#pragma once

#include "message_types.hpp"
#include "scene_params.hpp"

namespace ocean::scene_wire {

// depth_m: the sim's infinity is the wire's 0, and back.
double wire_depth(double sim_depth_m);
double sim_depth(double wire_depth_m);

wire::Spectrum to_wire(sim::SpectrumKind kind);
wire::Spreading to_wire(sim::SpreadingKind kind);
sim::SpectrumKind to_sim(wire::Spectrum spectrum);
sim::SpreadingKind to_sim(wire::Spreading spreading);

protocol::SceneParams to_wire(const sim::SceneParams& scene);
// Not validated: a scene off the wire goes through sim::validate (or the Ocean constructor) next.
sim::SceneParams to_sim(const protocol::SceneParams& scene);

}  // namespace ocean::scene_wire
