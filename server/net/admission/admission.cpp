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

}  // namespace ocean::server
