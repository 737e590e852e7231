#include "server_log.hpp"

#include <spdlog/spdlog.h>

namespace ocean::server {

bool set_log_level(std::string_view level) {
  const spdlog::level::level_enum parsed = spdlog::level::from_str(std::string(level));
  if (parsed == spdlog::level::off && level != "off") return false;
  spdlog::set_level(parsed);
  return true;
}

void log_connect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                 std::string_view profile) {
  spdlog::info("connect session={} transport={} peer={} profile={}", session_id, transport, peer, profile);
}

void log_disconnect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                    std::string_view reason) {
  spdlog::info("disconnect session={} transport={} peer={} reason={}", session_id, transport, peer, reason);
}

void log_reject(std::string_view transport, std::string_view peer, std::string_view reason, bool per_packet) {
  spdlog::log(per_packet ? spdlog::level::debug : spdlog::level::info, "reject transport={} peer={} reason={}",
              transport, peer, reason);
}

}  // namespace ocean::server
