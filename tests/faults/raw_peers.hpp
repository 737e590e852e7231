// Misbehaving peers built on plain blocking sockets, so a test controls every byte and every
// stall: RawTcp (connect, send raw bytes, read verified server messages, close with FIN or RST)
// and RawUdp (send datagrams from a chosen loopback address, count what comes back).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "message_types.hpp"
#include "tcp_framer.hpp"

namespace ocean::faults {

class RawTcp {
 public:
  // receive_buffer_bytes > 0 sets SO_RCVBUF before connecting (a small window for a stalled reader);
  // local_ip binds the connection to that loopback address (another address range than 127.0.0.1:
  // "127.0.1.2").
  explicit RawTcp(std::uint16_t port, int receive_buffer_bytes = 0, const char* local_ip = nullptr);
  ~RawTcp();
  RawTcp(RawTcp&& other) noexcept;
  RawTcp(const RawTcp&) = delete;
  RawTcp& operator=(const RawTcp&) = delete;

  bool connected() const { return fd_ >= 0 && connected_; }
  // Sends all bytes (blocking up to 1 s); false when the connection is gone or full.
  bool send(std::span<const std::uint8_t> bytes);
  // The next verified server message within timeout_s; nullopt on timeout, close or a bad message.
  std::optional<protocol::AnyMessage> read_message(double timeout_s);
  // The bytes that arrive within timeout_s, unparsed (empty on timeout or close).
  std::vector<std::uint8_t> read_raw(double timeout_s);
  // Sends the Hello and reads until the Welcome (frames before it are skipped).
  std::optional<protocol::Welcome> handshake(const protocol::Hello& hello, double timeout_s = 3.0);
  // Reads until the server closes; returns the Error or Bye seen (if any) and whether it closed.
  struct Ending {
    bool closed = false;
    std::optional<protocol::Error> error;
    std::optional<protocol::Bye> bye;
  };
  Ending wait_closed(double timeout_s);
  void close_with_reset();  // SO_LINGER 0: the peer sees RST, not FIN
  void close();

 private:
  int fd_ = -1;
  bool connected_ = false;
  protocol::TcpFramer framer_;
  std::vector<std::uint8_t> pending_;  // read but not yet fed
};

// A ParamChange sent on an admin session and its answer: a SceneUpdate naming its request_id
// (applied), or an Error; neither within timeout_s: both empty.
struct ParamChangeAnswer {
  bool applied = false;
  std::optional<protocol::Reason> error;
};
ParamChangeAnswer send_param_change(RawTcp& admin, const protocol::ParamChange& change, double timeout_s);

class RawUdp {
 public:
  explicit RawUdp(const std::string& local_ip = "127.0.0.1");
  ~RawUdp();
  RawUdp(const RawUdp&) = delete;
  RawUdp& operator=(const RawUdp&) = delete;

  void send_to(std::uint16_t port, std::span<const std::uint8_t> bytes);
  // Reads whatever arrived (non-blocking) and adds it to bytes_in.
  void drain();
  std::uint64_t bytes_out() const { return bytes_out_; }
  std::uint64_t bytes_in() const { return bytes_in_; }
  std::uint64_t datagrams_out() const { return datagrams_out_; }

 private:
  int fd_ = -1;
  std::uint64_t bytes_out_ = 0, bytes_in_ = 0, datagrams_out_ = 0;
};

// Lowers the calling thread's CPU priority, so attackers in the test process do not starve the
// well-behaved clients' thread on a small machine (the server still gets everything they send).
void lower_thread_priority();

}  // namespace ocean::faults
