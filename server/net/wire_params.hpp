// The scene and stream parameters as the Welcome and SceneUpdate carry them: the sim's scene
// with deep water (infinity) written as depth 0, and a codec StreamConfig as StreamParams.
#pragma once

#include "message_types.hpp"
#include "scene_params.hpp"
#include "stream_config.hpp"

namespace ocean::server {

protocol::SceneParams wire_scene(const sim::SceneParams& scene);
protocol::StreamParams wire_stream(const codec::StreamConfig& config);

}  // namespace ocean::server
