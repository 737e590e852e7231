// Admission: who may hold a connection before it has said Hello. Viewer slots (--max-clients) are
// for welcomed sessions only; connections that have not yet sent their Hello share a small budget
// of their own (--max-handshakes), with a share per address (--max-handshakes-per-ip), so silent
// or slow sockets from one place can neither take the viewers' slots nor the handshakes of other
// addresses; and one address holds at most --max-connections-per-ip connections in all. Counts
// are dropped with the address's last connection. (Admin token guesses: core_admin.cpp.)
#pragma once

#include <asio/ip/address.hpp>

#include <cstddef>
#include <map>
#include <string>

namespace ocean::server {

struct AdmissionLimits {
  int max_handshakes = 256;             // connections before their Hello, all addresses
  int max_handshakes_per_address = 32;  // of those, from one address
  int max_connections_per_address = 0;  // welcomed or not, from one address; 0 = no limit
};

class Admission {
 public:
  explicit Admission(AdmissionLimits limits) : limits_(limits) {}

  // "" and the connection counts as handshaking; else the metrics label of the limit it hit.
  std::string admit(const asio::ip::address& address);
  void welcomed(const asio::ip::address& address);  // its Hello was answered: no longer handshaking
  void closed(const asio::ip::address& address, bool was_welcomed);

  int handshaking() const { return handshaking_; }
  std::size_t tracked_addresses() const { return by_address_.size(); }
  const AdmissionLimits& limits() const { return limits_; }

 private:
  struct PerAddress {
    int handshaking = 0;
    int connections = 0;
  };
  void forget_if_empty(std::map<asio::ip::address, PerAddress>::iterator it);

  AdmissionLimits limits_;
  int handshaking_ = 0;
  std::map<asio::ip::address, PerAddress> by_address_;
};

}  // namespace ocean::server
