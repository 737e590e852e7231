#include "server_log.hpp"

#include <chrono>
#include <mutex>

namespace ocean::server {
namespace {

struct Limited {
  std::mutex mutex;
  LogLimiter limiter;
  std::function<void(std::string_view)> hook;
};

Limited& limited() {
  static Limited instance;
  return instance;
}

double monotonic_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

bool set_log_level(std::string_view level) {
  const spdlog::level::level_enum parsed = spdlog::level::from_str(std::string(level));
  if (parsed == spdlog::level::off && level != "off") return false;
  spdlog::set_level(parsed);
  return true;
}

bool log_allowed(std::string_view reason, std::string_view peer) {
  Limited& l = limited();
  std::lock_guard lock(l.mutex);
  if (l.limiter.allow(reason, peer, monotonic_s())) return true;
  if (l.hook) l.hook(reason);
  return false;
}

void flush_log_summary() {
  Limited& l = limited();
  std::vector<std::pair<std::string, std::uint64_t>> summary;
  {
    std::lock_guard lock(l.mutex);
    summary = l.limiter.take_summary(monotonic_s());
  }
  for (const auto& [reason, lines] : summary)
    spdlog::warn("log suppressed reason={} lines={} (rate limit per reason and peer; see ocean_log_suppressed_total)",
                 reason, lines);
}

void set_log_suppressed_hook(std::function<void(std::string_view reason)> hook) {
  Limited& l = limited();
  std::lock_guard lock(l.mutex);
  l.hook = std::move(hook);
}

void set_log_limits(const LogLimiter::Limits& limits) {
  Limited& l = limited();
  std::lock_guard lock(l.mutex);
  l.limiter = LogLimiter(limits);
}

void log_connect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                 std::string_view profile) {
  log_limited(spdlog::level::info, "connect", peer, "connect session={} transport={} peer={} profile={}", session_id,
              transport, peer, profile);
}

void log_disconnect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                    std::string_view reason) {
  log_limited(spdlog::level::info, "disconnect", peer, "disconnect session={} transport={} peer={} reason={}",
              session_id, transport, peer, reason);
}

void log_reject(std::string_view transport, std::string_view peer, std::string_view reason, bool per_packet) {
  log_limited(per_packet ? spdlog::level::debug : spdlog::level::info, reason, peer,
              "reject transport={} peer={} reason={}", transport, peer, reason);
}

}  // namespace ocean::server
