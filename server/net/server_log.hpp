// Server log lines: one per connect, disconnect and reject, each with its reason, in a fixed
// key=value shape so they can be grepped and counted. Uses spdlog's default logger.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace ocean::server {

// Sets the level from "trace".."off"; false (level unchanged) for an unknown name.
bool set_log_level(std::string_view level);

// "tcp" or "udp" and the peer as "ip:port".
void log_connect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                 std::string_view profile);
void log_disconnect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                    std::string_view reason);
// A refused connection or packet. Per-packet rejects are logged at debug so a flood cannot fill the
// log; connection rejects at info. `reason` is a short token also used as a metric label.
void log_reject(std::string_view transport, std::string_view peer, std::string_view reason, bool per_packet = false);

}  // namespace ocean::server
