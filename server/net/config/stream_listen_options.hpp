// The optional stream transports' listen options (--ws-listen), one per row of kStreamTransports
// (stream_transports.hpp) after the primary: ADDR:PORT|off, off by default, into
// ServerConfig::stream_listen under the transport's name. config_options() lists them beside kOptions.
#pragma once

#include "config_options.hpp"

#include <span>

namespace ocean::server {

std::span<const ConfigOption> stream_listen_options();

}  // namespace ocean::server
