#include "log_limiter.hpp"

namespace ocean::server {

std::string_view peer_address(std::string_view peer) {
  const std::size_t colon = peer.rfind(':');
  if (colon == std::string_view::npos) return peer;
  if (!peer.empty() && peer.front() == '[') return peer.substr(0, peer.find(']') + 1);
  if (peer.find(':') != colon) return peer;  // a bare IPv6 address: no port to strip
  return peer.substr(0, colon);
}

void LogLimiter::roll(double now_s) {
  if (window_start_s_ >= 0.0 && now_s - window_start_s_ < limits_.window_s) return;
  for (auto& [reason, count] : suppressed_)
    if (count > 0) ended_.emplace_back(reason, count);
  suppressed_.clear();
  per_peer_.clear();
  per_reason_.clear();
  window_start_s_ = now_s;
}

bool LogLimiter::allow(std::string_view reason, std::string_view peer, double now_s) {
  roll(now_s);
  auto by_reason = per_reason_.find(reason);
  if (by_reason == per_reason_.end()) by_reason = per_reason_.emplace(std::string(reason), 0).first;
  std::string key(reason);
  key += ' ';
  key += peer_address(peer);
  auto by_peer = per_peer_.find(key);
  if (by_peer == per_peer_.end() && per_peer_.size() < limits_.max_peers) by_peer = per_peer_.emplace(key, 0).first;
  const bool peer_ok = by_peer == per_peer_.end() || by_peer->second < limits_.per_peer;
  if (peer_ok && by_reason->second < limits_.per_reason) {
    ++by_reason->second;
    if (by_peer != per_peer_.end()) ++by_peer->second;
    return true;
  }
  auto left_out = suppressed_.find(reason);
  if (left_out == suppressed_.end()) left_out = suppressed_.emplace(std::string(reason), 0).first;
  ++left_out->second;
  ++suppressed_total_;
  return false;
}

std::vector<std::pair<std::string, std::uint64_t>> LogLimiter::take_summary(double now_s) {
  roll(now_s);
  return std::exchange(ended_, {});
}

}  // namespace ocean::server
