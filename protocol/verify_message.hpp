// verify_message(): the one gate every received byte passes before anything reads it. Checks the
// framing, runs the FlatBuffers Verifier, then the meaning of every field (PROTOCOL.md lists the
// rules). Pure: bytes in, a Verified out; it never throws and never changes any state.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "ocean_generated.h"
#include "wire_limits.hpp"
#include "wire_reason.hpp"

namespace ocean::protocol {

enum class Sender : std::uint8_t { client, server };

struct VerifyOptions {
  Sender sender = Sender::client;                  // who sent the bytes: the receiver's peer
  wire::Transport transport = wire::Transport::tcp;  // where they came from
  std::size_t max_message_bytes = kDefaultMaxMessageBytes;  // TCP limit; UDP always kMaxDatagram
};

struct Verified {
  bool ok = false;
  Reason reason = Reason::ok;
  const wire::Message* message = nullptr;  // set only when ok; points into the verified bytes
  std::string_view field;                  // what failed, e.g. "FrameChunk.index"; static text
  std::string_view rule;                   // what was expected, e.g. "index < count"; static text
  explicit operator bool() const { return ok; }
};

// bytes: one whole message, size prefix included (a TcpFramer message or a UDP datagram), whose
// first byte is 8-byte aligned (std::vector storage is). On success the message aliases bytes.
Verified verify_message(std::span<const std::uint8_t> bytes, const VerifyOptions& options);

// "bad_chunk_index in FrameChunk.index: expected index < count" - for logs and Error.text.
std::string describe(const Verified& result);

// The session id and cookie a client message carries (UdpHello, Ack, KeyframeRequest, Ping);
// Reason::unexpected_message for other types. A UDP server calls this after verify_message with
// the session it looked up; the cookie comparison takes the same time wherever bytes differ.
Reason check_udp_sender(const wire::Message& message, std::uint64_t session_id,
                        std::span<const std::uint8_t> cookie);

// Which side may send a message type, and whether it may travel over UDP / TCP.
bool may_send(Sender sender, wire::Body type);
bool may_travel(wire::Transport transport, wire::Body type);

}  // namespace ocean::protocol
