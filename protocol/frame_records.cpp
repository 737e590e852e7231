// Frame record block layout: LEB128 varints, records relative to the newest tick (PROTOCOL.md 7).
#include "frame_records.hpp"

#include "wire_limits.hpp"

#include <algorithm>
#include <stdexcept>

namespace ocean::protocol {
namespace {

void put_varint(Bytes& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(v));
}

// At most 10 bytes; the tenth may carry only the top bit of a 64-bit value.
bool get_varint(std::span<const std::uint8_t> in, std::size_t& pos, std::uint64_t& v) {
  v = 0;
  for (int i = 0; i < 10; ++i) {
    if (pos >= in.size()) return false;
    const std::uint8_t b = in[pos++];
    if (i == 9 && b > 1) return false;
    v |= static_cast<std::uint64_t>(b & 0x7F) << (7 * i);
    if ((b & 0x80) == 0) return true;
  }
  return false;
}

FrameBlockResult fail(Reason reason, std::string rule) { return {reason, std::move(rule)}; }

}  // namespace

Bytes encode_frame_block(std::span<const FrameRecord> records) {
  for (const FrameRecord& r : records)
    if (r.count == 0 || r.index >= r.count || (r.key ? r.baseline != r.tick : r.baseline >= r.tick))
      throw std::invalid_argument("encode_frame_block: a record's index, count or baseline is inconsistent");
  Bytes out;
  if (records.empty()) return out;
  Tick newest = 0;
  std::size_t size = 10;
  for (const FrameRecord& r : records) {
    newest = std::max(newest, r.tick);
    size += r.payload.size() + kMaxRecordOverheadBytes;
  }
  out.reserve(size);
  put_varint(out, newest);
  for (const FrameRecord& r : records) {
    put_varint(out, newest - r.tick);
    put_varint(out, r.key ? 0 : r.tick - r.baseline);
    put_varint(out, r.count - 1u);
    if (r.count > 1) put_varint(out, r.index);
    put_varint(out, r.payload.size());
    out.insert(out.end(), r.payload.begin(), r.payload.end());
  }
  return out;
}

Bytes frames_datagram(std::span<const FrameRecord> records) {
  Bytes block = encode_frame_block(records);
  block.insert(block.begin(), static_cast<std::uint8_t>(DatagramKind::frames));
  return block;
}

Bytes message_datagram(std::span<const std::uint8_t> message) {
  Bytes out;
  out.reserve(message.size() + 1);
  out.push_back(static_cast<std::uint8_t>(DatagramKind::message));
  out.insert(out.end(), message.begin(), message.end());
  return out;
}

FrameBlockResult decode_frame_block(std::span<const std::uint8_t> block, std::vector<FrameRecord>& out) {
  out.clear();
  std::size_t pos = 0;
  std::uint64_t newest = 0;
  if (block.empty()) return fail(Reason::empty, "a block holds at least one record");
  if (!get_varint(block, pos, newest)) return fail(Reason::truncated, "newest tick: a varint of at most 10 bytes");
  while (pos < block.size()) {
    if (out.size() == kMaxRecordsPerBlock) {
      out.clear();
      return fail(Reason::out_of_range, "at most 64 records per block");
    }
    std::uint64_t back = 0, lag = 0, count_minus_1 = 0, index = 0, length = 0;
    FrameBlockResult failure;  // reason ok until a check fails
    if (!get_varint(block, pos, back) || !get_varint(block, pos, lag) || !get_varint(block, pos, count_minus_1))
      failure = fail(Reason::truncated, "record header: varints of tick offset, lag and count");
    else if (back > newest)
      failure = fail(Reason::bad_sequence, "record tick offset <= the block's newest tick");
    else if (lag > kMaxFrameLag || lag > newest - back)
      failure = fail(Reason::bad_sequence, "record lag <= 1024 and <= its tick");
    else if (count_minus_1 >= kMaxChunksPerFrame)
      failure = fail(Reason::bad_chunk_index, "record count in [1, 4096]");
    else if (count_minus_1 > 0 && !get_varint(block, pos, index))
      failure = fail(Reason::truncated, "record index varint");
    else if (index > count_minus_1)
      failure = fail(Reason::bad_chunk_index, "record index < count");
    else if (!get_varint(block, pos, length) || length > block.size() - pos)
      failure = fail(Reason::truncated, "record payload within the block");
    if (failure.reason != Reason::ok) {
      out.clear();
      return failure;
    }
    FrameRecord r;
    r.tick = newest - back;
    r.key = lag == 0;
    r.baseline = r.tick - lag;
    r.count = static_cast<std::uint16_t>(count_minus_1 + 1);
    r.index = static_cast<std::uint16_t>(index);
    r.payload = block.subspan(pos, length);
    pos += length;
    out.push_back(r);
  }
  if (out.empty()) return fail(Reason::empty, "a block holds at least one record");
  return {};
}

}  // namespace ocean::protocol
