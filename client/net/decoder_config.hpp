// decoder_config(): the codec configuration a client builds from the server's Welcome. It must
// equal the server's encoder configuration bit for bit (server/net/wire_params.cpp maps the other way).
#pragma once

#include "message_types.hpp"
#include "stream_config.hpp"

namespace ocean::client {

codec::StreamConfig decoder_config(const protocol::Welcome& welcome);

}  // namespace ocean::client
