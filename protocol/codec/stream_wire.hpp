// The codec configuration a client builds from the server's wire messages: the stream from the
// Welcome, and the scene model of every SceneParams (Welcome, SceneUpdate). It must equal what the
// server's encoder was given bit for bit, so the server builds its own from the same functions
// (through wire_scene()). Target ocean_codec_wire: the codec plus the protocol's message types.
#pragma once

#include "message_types.hpp"
#include "scene_model.hpp"
#include "stream_config.hpp"

namespace ocean::codec {

StreamConfig decoder_config(const protocol::Welcome& welcome);
SceneModelParams scene_model_params(const protocol::SceneParams& scene);

}  // namespace ocean::codec
