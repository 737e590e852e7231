// TcpFramer: cuts a TCP byte stream into size-prefixed messages. Fed whatever a read returned,
// it answers need_more / good / bad like Asio's http request_parser, and refuses an oversized
// size prefix before consuming any body byte, so it never buffers more than max_message_bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "wire_limits.hpp"
#include "wire_reason.hpp"

namespace ocean::protocol {

class TcpFramer {
 public:
  enum class Status : std::uint8_t {
    need_more,  // every byte fed was consumed; the message is not complete yet
    good,       // message() holds one complete message; unconsumed bytes remain for the next feed
    bad,        // the stream is unusable (reason says why); close the connection
  };

  struct Result {
    Status status = Status::need_more;
    Reason reason = Reason::ok;  // set when status is bad
    std::size_t consumed = 0;    // bytes of the fed span this call used
  };

  // max_message_bytes: the largest whole message accepted, size prefix included.
  explicit TcpFramer(std::size_t max_message_bytes = kDefaultMaxMessageBytes);

  // Consumes bytes up to the end of one message at most. After good, the next feed starts a new
  // message; after bad, every feed answers bad with nothing consumed until reset().
  Result feed(std::span<const std::uint8_t> bytes);

  // The last complete message, size prefix included, 8-byte aligned: pass it to verify_message.
  // Valid after feed() answered good, until the next feed() or reset().
  std::span<const std::uint8_t> message() const;

  // Applies to the next message (e.g. Welcome.max_message_bytes once the handshake is done).
  void set_max_message_bytes(std::size_t max_message_bytes);
  std::size_t max_message_bytes() const { return max_message_bytes_; }

  // Bytes held of the message under way (0 between messages).
  std::size_t buffered_bytes() const;

  void reset();

 private:
  std::size_t max_message_bytes_;
  std::vector<std::uint8_t> buffer_;  // prefix + body of the message under way or just completed
  std::size_t expected_ = 0;          // whole message size once the prefix is read, else 0
  bool complete_ = false;
  Reason failure_ = Reason::ok;
};

}  // namespace ocean::protocol
