// A minimal receiving endpoint for the tests: verify, then parse the frame records of a FrameData
// message (TCP) or of a frames datagram (UDP, after its kind byte) and note every (tick, chunk
// index) taken, the way a client hands them to its decoder. Used to prove a rejected input leaves
// the receiver's state unchanged: a block is taken whole or not at all.
#pragma once

#include <cstring>
#include <utility>
#include <vector>

#include "frame_records.hpp"
#include "message_builders.hpp"
#include "sample_messages.hpp"
#include "verify_message.hpp"

namespace ocean::protocol::test {

// Copies bytes to an 8-byte aligned buffer (as a socket read into std::vector would be).
inline Bytes aligned_copy(std::span<const std::uint8_t> bytes) { return Bytes(bytes.begin(), bytes.end()); }

struct Receiver {
  std::vector<std::pair<Tick, std::uint16_t>> seen;  // (tick, index) of every record taken, in order
  std::size_t messages = 0;                          // verified messages that were not FrameData

  // One whole message (a TcpFramer message, or the message of a datagram).
  Reason receive(std::span<const std::uint8_t> bytes, const VerifyOptions& options) {
    const Verified verified = verify_message(bytes, options);
    if (!verified) return verified.reason;
    if (const auto* data = verified.message->body_as_FrameData())
      return take_block({data->frames()->data(), data->frames()->size()});  // required, non-empty: verified
    ++messages;
    return Reason::ok;
  }

  // One server datagram of version 2: its kind byte, then a block or a message.
  Reason receive_datagram(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) return Reason::empty;
    if (bytes.size() > kMaxDatagram) return Reason::oversized;
    switch (static_cast<DatagramKind>(bytes[0])) {
      case DatagramKind::frames: return take_block(bytes.subspan(1));
      case DatagramKind::message: return receive(aligned_copy(bytes.subspan(1)), from(Sender::server, wire::Transport::udp));
    }
    return Reason::unknown_message_type;
  }

  Reason take_block(std::span<const std::uint8_t> block) {
    std::vector<FrameRecord> records;
    const FrameBlockResult parsed = decode_frame_block(block, records);
    if (!parsed) return parsed.reason;
    for (const FrameRecord& r : records) seen.emplace_back(r.tick, r.index);
    return Reason::ok;
  }

  bool operator==(const Receiver&) const = default;
};

// A receiver with history: a keyframe of tick 100 in three chunks over TCP, and the first chunk of
// the delta of tick 101 in a frames datagram.
inline Receiver busy_receiver() {
  const Bytes key(50, 1), delta(20, 2);
  std::vector<FrameRecord> key_chunks;
  for (std::uint16_t i = 0; i < 3; ++i)
    key_chunks.push_back(FrameRecord{100, 100, true, i, 3, std::span(key).subspan(i * 20u, i == 2 ? 10u : 20u)});
  const FrameRecord delta_chunk{101, 100, false, 0, 2, delta};
  Receiver receiver;
  receiver.receive(encode(FrameData{encode_frame_block(key_chunks)}), from_server());
  receiver.receive_datagram(frames_datagram(std::span(&delta_chunk, 1)));
  return receiver;
}

}  // namespace ocean::protocol::test
