// A minimal receiving endpoint for the tests: verify, then hand FrameChunks to a ChunkAssembler,
// the way a client does. Used to prove a rejected input leaves the receiver's state unchanged.
#pragma once

#include <cstring>

#include "chunk_assembler.hpp"
#include "message_builders.hpp"
#include "sample_messages.hpp"
#include "verify_message.hpp"

namespace ocean::protocol::test {

struct Receiver {
  ChunkAssembler assembler;
  std::size_t frames = 0;

  Reason receive(std::span<const std::uint8_t> bytes, const VerifyOptions& options) {
    const Verified verified = verify_message(bytes, options);
    if (!verified) return verified.reason;
    if (const auto* chunk = verified.message->body_as_FrameChunk()) {
      ChunkAssembler::Outcome outcome = assembler.add(*chunk);
      if (outcome.reason != Reason::ok) return outcome.reason;
      if (outcome.frame) ++frames;
    }
    return Reason::ok;
  }

  bool operator==(const Receiver&) const = default;
};

// A receiver with history: one completed keyframe (tick 100) and one delta frame half received.
inline Receiver busy_receiver() {
  Receiver receiver;
  for (const Bytes& chunk : split_frame(FrameHeader{100, 100, true, 1}, Bytes(50, 1), 20))
    receiver.receive(chunk, from_server());
  const auto delta = split_frame(FrameHeader{101, 100, false, 1}, Bytes(50, 2), 20);
  receiver.receive(delta[0], from_server());
  return receiver;
}

// Copies bytes to an 8-byte aligned buffer (as a socket read into std::vector would be).
inline Bytes aligned_copy(std::span<const std::uint8_t> bytes) { return Bytes(bytes.begin(), bytes.end()); }

}  // namespace ocean::protocol::test
