// Forwarding only: the hub (session_hub.cpp, hub_ticks.cpp) is being reworked on another branch and
// still calls these names. The conversions live in protocol/scene_wire/scene_wire.hpp (scene) and
// protocol/codec/stream_wire.hpp (stream); once the hub includes those, delete this header.
#pragma once

#include "scene_wire.hpp"
#include "stream_wire.hpp"

namespace ocean::server {

inline protocol::SceneParams wire_scene(const sim::SceneParams& scene) { return scene_wire::to_wire(scene); }
using codec::wire_stream;

}  // namespace ocean::server
