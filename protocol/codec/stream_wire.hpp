// The codec configuration as the wire carries it, both directions: the server writes its encoder's
// StreamConfig into the Welcome, a client builds its decoder's from that Welcome, and both build
// the scene model from SceneParams (protocol/scene_wire). The two ends must agree bit for bit, so
// they share these functions. Target ocean_codec_wire: the codec plus the protocol's message types.
// Depth is 0 for deep water on the wire and in StreamConfig alike, so nothing here translates it.
#pragma once

#include "message_types.hpp"
#include "stream_config.hpp"

namespace ocean::codec {

protocol::StreamParams wire_stream(const StreamConfig& config);
StreamConfig decoder_config(const protocol::Welcome& welcome);

}  // namespace ocean::codec
