// SharedBytes: one message's bytes, built once and queued to any number of sessions.
#pragma once

#include "message_types.hpp"

#include <memory>

namespace ocean::server {

using SharedBytes = std::shared_ptr<const protocol::Bytes>;

inline SharedBytes share(protocol::Bytes bytes) { return std::make_shared<const protocol::Bytes>(std::move(bytes)); }

}  // namespace ocean::server
