// libFuzzer harness for decode_frame_block (frame_records.hpp), the reader of every frame the
// server sends in version 2: a frames datagram after its kind byte, or a FrameData message's block.
// Input: one block.
// Invariants: refused <=> no records, and a refusal names its rule; accepted records obey the
// block's rules (1..64 records, count in [1, 4096], index < count, key <=> baseline == tick, lag
// <= kMaxFrameLag) and their payloads lie inside the input without overlapping; re-encoding gives
// the same records in no more bytes (the encoder writes the shortest form), and the frames
// datagram of the records is the kind byte plus that block.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "frame_records.hpp"
#include "fuzz_check.hpp"
#include "wire_limits.hpp"

using namespace ocean::protocol;

namespace {

bool same_record(const FrameRecord& a, const FrameRecord& b) {
  return a.tick == b.tick && a.baseline == b.baseline && a.key == b.key && a.index == b.index && a.count == b.count &&
         a.payload.size() == b.payload.size() && std::equal(a.payload.begin(), a.payload.end(), b.payload.begin());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> block(data, size);
  std::vector<FrameRecord> records;
  const FrameBlockResult parsed = decode_frame_block(block, records);
  FUZZ_REQUIRE(static_cast<bool>(parsed) == (parsed.reason == Reason::ok));
  if (!parsed) {
    FUZZ_REQUIRE(records.empty());
    FUZZ_REQUIRE(!parsed.rule.empty());
    return 0;
  }
  FUZZ_REQUIRE(parsed.rule.empty());
  FUZZ_REQUIRE(!records.empty() && records.size() <= kMaxRecordsPerBlock);
  const std::uint8_t* next_payload = data;  // payloads follow each other through the block
  for (const FrameRecord& r : records) {
    FUZZ_REQUIRE(r.count >= 1 && r.count <= kMaxChunksPerFrame);
    FUZZ_REQUIRE(r.index < r.count);
    FUZZ_REQUIRE(r.baseline <= r.tick && r.tick - r.baseline <= kMaxFrameLag);
    FUZZ_REQUIRE(r.key == (r.baseline == r.tick));
    if (!r.payload.empty()) {
      FUZZ_REQUIRE(r.payload.data() >= next_payload);
      FUZZ_REQUIRE(r.payload.data() + r.payload.size() <= data + size);
      next_payload = r.payload.data() + r.payload.size();
    }
  }

  const Bytes again = encode_frame_block(records);
  FUZZ_REQUIRE(again.size() <= size);
  std::vector<FrameRecord> second;
  FUZZ_REQUIRE(decode_frame_block(again, second));
  FUZZ_REQUIRE(second.size() == records.size());
  for (std::size_t i = 0; i < records.size(); ++i) FUZZ_REQUIRE(same_record(records[i], second[i]));
  FUZZ_REQUIRE(encode_frame_block(second) == again);  // the shortest form is a fixed point

  const Bytes datagram = frames_datagram(records);
  FUZZ_REQUIRE(datagram.size() == again.size() + 1);
  FUZZ_REQUIRE(datagram[0] == static_cast<std::uint8_t>(DatagramKind::frames));
  FUZZ_REQUIRE(std::equal(again.begin(), again.end(), datagram.begin() + 1));
  return 0;
}
