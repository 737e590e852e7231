// AdminLink: one TCP connection to an ocean-server that sends messages and waits for the next
// verified one, every wait bounded by one deadline for the whole exchange - a CLI must never hang
// on a server that accepts the connection and then says nothing.
#pragma once

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "message_types.hpp"
#include "server_list.hpp"
#include "tcp_framer.hpp"

namespace ocean::admin {

class AdminLink {
 public:
  using Clock = std::chrono::steady_clock;

  explicit AdminLink(double timeout_s);

  // False with `error` naming the server and the cause (refused, unresolvable, timed out).
  bool connect(const client::ServerEndpoint& server, std::string& error);
  bool send(const protocol::Bytes& bytes, std::string& error);
  // The next verified server message; nullopt with `error` when the connection closed, a message
  // failed verification, or `until` (default: the deadline) passed - timed_out() tells the last.
  std::optional<protocol::AnyMessage> receive(std::string& error, std::optional<Clock::time_point> until = {});
  bool timed_out() const { return timed_out_; }
  // After the Welcome: its limit applies to every later message.
  void set_max_message_bytes(std::size_t bytes);

 private:
  // Runs the loop until `done` or `until`; on time out, closes the socket and returns false.
  bool run_until(const bool& done, Clock::time_point until);

  asio::io_context io_;
  asio::ip::tcp::socket socket_;
  Clock::time_point deadline_;
  protocol::TcpFramer framer_;
  std::size_t max_message_bytes_;
  std::vector<std::uint8_t> pending_;  // received bytes the framer has not consumed yet
  bool timed_out_ = false;
};

}  // namespace ocean::admin
