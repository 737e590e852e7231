// Frame reassembly: every check happens before the first change, so a rejection changes nothing.
#include "chunk_assembler.hpp"

#include <algorithm>

namespace ocean::protocol {
namespace {

ChunkAssembler::Outcome rejected(Reason reason) { return ChunkAssembler::Outcome{reason, false, std::nullopt}; }

}  // namespace

ChunkAssembler::ChunkAssembler() : ChunkAssembler(Limits{}) {}

ChunkAssembler::ChunkAssembler(Limits limits) : limits_(limits) {}

Bytes ChunkAssembler::Frame::joined() const {
  Bytes bytes;
  for (const Bytes& chunk : chunks) bytes.insert(bytes.end(), chunk.begin(), chunk.end());
  return bytes;
}

ChunkAssembler::Outcome ChunkAssembler::add(const wire::FrameChunk& chunk) {
  // verify_message() already guarantees this; checked again because an index is about to be used.
  if (chunk.count() == 0 || chunk.index() >= chunk.count()) return rejected(Reason::bad_chunk_index);
  const std::uint32_t tick = chunk.tick();
  if (completed(tick) || (acked_ && tick < acked_->latest_tick && acked_->latest_tick - tick > kAckWindowTicks))
    return rejected(Reason::stale_tick);

  const FrameHeader header{tick, chunk.baseline(), chunk.key(), chunk.profile_id()};
  const std::size_t part_bytes = chunk.payload() ? chunk.payload()->size() : 0;
  auto it = std::find_if(pending_.begin(), pending_.end(),
                         [&](const Pending& p) { return p.header.tick == tick; });
  if (it != pending_.end()) {
    if (it->header != header) return rejected(Reason::bad_sequence);
    if (it->count != chunk.count()) return rejected(Reason::bad_chunk_index);
    if (it->have[chunk.index()]) return Outcome{Reason::ok, true, std::nullopt};
    if (it->bytes + part_bytes > limits_.max_frame_bytes) return rejected(Reason::oversized);
  } else {
    if (part_bytes > limits_.max_frame_bytes) return rejected(Reason::oversized);
    if (limits_.max_frames_in_flight == 0) return rejected(Reason::stale_tick);
    if (pending_.size() >= limits_.max_frames_in_flight) {
      auto oldest = std::min_element(pending_.begin(), pending_.end(),
                                     [](const Pending& a, const Pending& b) { return a.header.tick < b.header.tick; });
      if (oldest->header.tick > tick) return rejected(Reason::stale_tick);
      pending_.erase(oldest);
    }
    Pending fresh;
    fresh.header = header;
    fresh.count = chunk.count();
    fresh.parts.resize(chunk.count());
    fresh.have.assign(chunk.count(), 0);
    pending_.push_back(std::move(fresh));
    it = pending_.end() - 1;
  }

  if (part_bytes) it->parts[chunk.index()].assign(chunk.payload()->begin(), chunk.payload()->end());
  it->have[chunk.index()] = 1;
  it->bytes += part_bytes;
  if (++it->received < it->count) return Outcome{};

  Frame frame{it->header, std::move(it->parts)};
  pending_.erase(it);
  acked_ = acked_ ? acked_->with(tick) : AckWindow{tick, 0};
  // Frames that fell out of the ack window can never complete: add() would call them stale.
  const std::uint32_t latest = acked_->latest_tick;
  std::erase_if(pending_, [&](const Pending& p) {
    return p.header.tick < latest && latest - p.header.tick > kAckWindowTicks;
  });
  return Outcome{Reason::ok, false, std::move(frame)};
}

}  // namespace ocean::protocol
