#include "admission.hpp"

namespace ocean::server {

std::string Admission::admit(const asio::ip::address& address) {
  if (handshaking_ >= limits_.max_handshakes) return "handshakes_full";
  const auto it = by_address_.try_emplace(address).first;
  PerAddress& mine = it->second;
  std::string refused;
  if (mine.handshaking >= limits_.max_handshakes_per_address)
    refused = "address_handshakes_full";
  else if (limits_.max_connections_per_address > 0 && mine.connections >= limits_.max_connections_per_address)
    refused = "address_connections_full";
  if (!refused.empty()) {
    forget_if_empty(it);
    return refused;
  }
  ++mine.handshaking;
  ++mine.connections;
  ++handshaking_;
  return {};
}

void Admission::welcomed(const asio::ip::address& address) {
  const auto it = by_address_.find(address);
  if (it == by_address_.end() || it->second.handshaking == 0) return;
  --it->second.handshaking;
  --handshaking_;
}

void Admission::closed(const asio::ip::address& address, bool was_welcomed) {
  const auto it = by_address_.find(address);
  if (it == by_address_.end()) return;
  if (!was_welcomed && it->second.handshaking > 0) {
    --it->second.handshaking;
    --handshaking_;
  }
  if (it->second.connections > 0) --it->second.connections;
  forget_if_empty(it);
}

void Admission::forget_if_empty(std::map<asio::ip::address, PerAddress>::iterator it) {
  if (it->second.handshaking == 0 && it->second.connections == 0) by_address_.erase(it);
}

bool Admission::token_failure(const asio::ip::address& address, double now_s) {
  if (!tokens_.count(address)) make_token_room(now_s);
  Tokens& mine = tokens_[address];
  if (mine.failures == 0 || now_s - mine.window_start_s >= limits_.token_window_s) mine = Tokens{0, now_s};
  ++mine.failures;
  return mine.failures >= limits_.token_failures_per_address;
}

bool Admission::tokens_blocked(const asio::ip::address& address, double now_s) const {
  const auto it = tokens_.find(address);
  return it != tokens_.end() && it->second.failures >= limits_.token_failures_per_address &&
         now_s - it->second.window_start_s < limits_.token_window_s;
}

// Expired windows go first; if every entry is live, the table is full of guessers, and forgetting
// one of them (the lowest address) only gives that address a fresh budget of a few guesses.
void Admission::make_token_room(double now_s) {
  if (tokens_.size() < limits_.max_token_addresses) return;
  std::erase_if(tokens_, [&](const auto& entry) { return now_s - entry.second.window_start_s >= limits_.token_window_s; });
  if (tokens_.size() >= limits_.max_token_addresses) tokens_.erase(tokens_.begin());
}

}  // namespace ocean::server
