// WebSocketClient: the client's side of RFC 6455 for a ClientConnection that reaches the server's
// --ws-listen as a browser does (ocean-loadtest --transport ws): the upgrade request with a fresh
// key, the server's answer checked (101 and its Sec-WebSocket-Accept), each protocol message sent
// as one masked binary frame, and whole binary messages out of what the server sends (fragments
// joined, Pings answered, a close frame or a text frame ends it). Pure: bytes in, bytes out.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace ocean::client {

class WebSocketClient {
 public:
  // seed: the keys' and masks' randomness (a load test's client i uses its own).
  WebSocketClient(std::uint64_t seed, std::size_t max_message_bytes);

  // The upgrade request for ws://host:port/ (a new key each time: a new connection).
  std::string upgrade_request(const std::string& host, const std::string& port);
  // The Sec-WebSocket-Accept a server answers `key` with (RFC 6455 4.2.2).
  static std::string accept_for(const std::string& key);
  bool open() const { return open_; }
  void set_max_message_bytes(std::size_t bytes) { max_message_bytes_ = bytes; }

  // What the server sent, in order: first its answer to the upgrade, then frames. The call that
  // completes the answer stops there (open() turns true; what came behind it waits for the next
  // call, with no bytes or more). Each whole binary message goes to on_message; what must be
  // answered (a Pong) to on_reply, as bytes to write. Empty while all is well, else why the
  // connection ends.
  std::string feed(std::span<const std::uint8_t> bytes, const std::function<void(std::span<const std::uint8_t>)>& on_message,
                   const std::function<void(std::vector<std::uint8_t>)>& on_reply);

  // One masked, final binary frame holding `message`.
  std::vector<std::uint8_t> frame(std::span<const std::uint8_t> message, std::uint8_t opcode = 2);

 private:
  std::string read_answer();
  std::string read_frames(const std::function<void(std::span<const std::uint8_t>)>& on_message,
                          const std::function<void(std::vector<std::uint8_t>)>& on_reply);

  std::mt19937_64 random_;
  std::size_t max_message_bytes_;
  std::string expected_accept_;
  bool open_ = false;
  std::vector<std::uint8_t> buffer_;   // bytes not yet consumed
  std::vector<std::uint8_t> message_;  // a fragmented message's parts so far
  bool in_message_ = false;
};

}  // namespace ocean::client
