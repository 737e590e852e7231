// SceneParams as a JSON object, every double with 17 significant digits: a scene must survive a
// round trip through the printout bit for bit (the codec needs the exact doubles, CODEC.md 7.6).
#pragma once

#include <string>

#include "message_types.hpp"

namespace ocean::admin {

std::string scene_json(const protocol::SceneParams& scene);

}  // namespace ocean::admin
