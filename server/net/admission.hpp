// Admission: who may hold a connection before it has said Hello, and who may keep guessing the
// admin token. Viewer slots (--max-clients) are for welcomed sessions only; connections that have
// not yet sent their Hello share a small budget of their own (--max-handshakes), with a share per
// address (--max-handshakes-per-ip), so silent or slow sockets from one place can neither take
// the viewers' slots nor the handshakes of other addresses. Wrong admin tokens are counted per
// address over a window: beyond the budget every ParamChange from there is refused unread.
// Connection counts are dropped with the address's last connection; token failures outlive the
// connection (reconnecting must not reset them) in a table of at most max_token_addresses.
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
  int token_failures_per_address = 10;  // wrong admin tokens per window from one address
  double token_window_s = 60.0;
  std::size_t max_token_addresses = 4096;
};

class Admission {
 public:
  explicit Admission(AdmissionLimits limits) : limits_(limits) {}

  // "" and the connection counts as handshaking; else the metrics label of the limit it hit.
  std::string admit(const asio::ip::address& address);
  void welcomed(const asio::ip::address& address);  // its Hello was answered: no longer handshaking
  void closed(const asio::ip::address& address, bool was_welcomed);
  // Counts one wrong admin token; true when the address has used up its budget.
  bool token_failure(const asio::ip::address& address, double now_s);
  bool tokens_blocked(const asio::ip::address& address, double now_s) const;

  int handshaking() const { return handshaking_; }
  std::size_t tracked_addresses() const { return by_address_.size(); }
  const AdmissionLimits& limits() const { return limits_; }

 private:
  struct PerAddress {
    int handshaking = 0;
    int connections = 0;
  };
  struct Tokens {
    int failures = 0;
    double window_start_s = 0.0;
  };
  void forget_if_empty(std::map<asio::ip::address, PerAddress>::iterator it);
  void make_token_room(double now_s);

  AdmissionLimits limits_;
  int handshaking_ = 0;
  std::map<asio::ip::address, PerAddress> by_address_;
  std::map<asio::ip::address, Tokens> tokens_;
};

}  // namespace ocean::server
