// Server log lines: one per connect, disconnect and reject, each with its reason, in a fixed
// key=value shape so they can be grepped and counted. Uses spdlog's default logger.
// Lines a client can cause are rate-limited per reason and peer address (LogLimiter): a flood
// writes a few lines and then one "log suppressed" summary per reason and window; every event is
// still counted in the metrics by its caller, and every suppressed line in ocean_log_suppressed_total.
#pragma once

#include "log_limiter.hpp"

#include <spdlog/spdlog.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace ocean::server {

// How a log line names a peer: HOST:PORT, an IPv6 host in brackets.
std::string peer_text(const auto& endpoint) {
  const auto address = endpoint.address();
  std::string text;  // appended piecewise: g++ 12 warns falsely (-Wrestrict) on "[" + std::string
  if (address.is_v6()) text += '[';
  text += address.to_string();
  if (address.is_v6()) text += ']';
  text += ':';
  text += std::to_string(endpoint.port());
  return text;
}

// Sets the level from "trace".."off"; false (level unchanged) for an unknown name.
bool set_log_level(std::string_view level);

// Whether a line about `reason` caused by `peer` may be written now (thread-safe). A false counts
// the line as suppressed; it is then reported in the next summary.
bool log_allowed(std::string_view reason, std::string_view peer);
// Writes the summaries of windows that have ended ("log suppressed reason=X lines=N"); the
// server calls it every tick, so a summary comes even after the flood stopped.
void flush_log_summary();
// Called once per suppressed line with its reason (the server counts them); empty to detach.
void set_log_suppressed_hook(std::function<void(std::string_view reason)> hook);
// Replaces the limits and forgets the counts (tests; the defaults suit a server).
void set_log_limits(const LogLimiter::Limits& limits);

// A line at `level` about an event a client can cause, subject to log_allowed(reason, peer).
template <typename... Args>
void log_limited(spdlog::level::level_enum level, std::string_view reason, std::string_view peer,
                 spdlog::format_string_t<Args...> format, Args&&... args) {
  if (!spdlog::should_log(level) || !log_allowed(reason, peer)) return;
  spdlog::log(level, format, std::forward<Args>(args)...);
}

// "tcp" or "udp" and the peer as "ip:port".
void log_connect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                 std::string_view profile);
void log_disconnect(std::uint64_t session_id, std::string_view transport, std::string_view peer,
                    std::string_view reason);
// A refused connection or packet. Per-packet rejects are logged at debug; connection rejects at
// info. `reason` is a short token also used as a metric label.
void log_reject(std::string_view transport, std::string_view peer, std::string_view reason, bool per_packet = false);

}  // namespace ocean::server
