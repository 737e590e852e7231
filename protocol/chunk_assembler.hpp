// ChunkAssembler: the receiving end of a stream of opaque frames. Collects verified FrameChunks
// into whole frames and keeps the AckWindow of complete ticks. (The codec's Decoder reassembles
// its own chunks; a client using it needs only ack_window().) A rejection changes nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "ack_window.hpp"
#include "message_types.hpp"

namespace ocean::protocol {

class ChunkAssembler {
 public:
  struct Limits {
    std::size_t max_frames_in_flight = 8;          // incomplete frames kept; the oldest goes first
    std::size_t max_frame_bytes = 4 * 1024 * 1024;  // one frame's payload
    bool operator==(const Limits&) const = default;
  };

  struct Frame {
    FrameHeader header;
    std::vector<Bytes> chunks;  // payloads by index
    Bytes joined() const;       // the payloads concatenated by index
  };

  struct Outcome {
    Reason reason = Reason::ok;  // not ok: the chunk was rejected and nothing changed
    bool duplicate = false;      // ok, but this chunk was already held: nothing changed
    std::optional<Frame> frame;  // set when this chunk completed its frame
  };

  ChunkAssembler();
  explicit ChunkAssembler(Limits limits);

  // chunk must come from a message verify_message() accepted. A duplicate of a chunk already
  // held is ok and changes nothing. Rejections: stale_tick (frame already complete, or older
  // than the 32-tick ack window), bad_sequence / bad_chunk_index (disagrees with earlier chunks
  // of its tick), oversized (frame above max_frame_bytes).
  Outcome add(const wire::FrameChunk& chunk);

  // The complete ticks to acknowledge; nullopt until the first frame completes.
  const std::optional<AckWindow>& ack_window() const { return acked_; }
  bool completed(std::uint32_t tick) const { return acked_ && acked_->contains(tick); }

  std::size_t frames_in_flight() const { return pending_.size(); }

  bool operator==(const ChunkAssembler&) const = default;

 private:
  struct Pending {
    FrameHeader header;
    std::uint16_t count = 0;
    std::uint16_t received = 0;
    std::size_t bytes = 0;
    std::vector<Bytes> parts;        // by index
    std::vector<std::uint8_t> have;  // by index: 1 once that chunk arrived
    bool operator==(const Pending&) const = default;
  };

  Limits limits_;
  std::vector<Pending> pending_;
  std::optional<AckWindow> acked_;
};

}  // namespace ocean::protocol
