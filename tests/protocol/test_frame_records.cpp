// Frame records (frame_records.hpp, PROTOCOL.md 7): the block layout byte for byte, round trips of
// keys, deltas and multi-chunk frames at any tick a 64-bit count reaches, and every refusal of
// decode_frame_block - each naming its reason and rule and leaving `out` empty.
#include <catch2/catch.hpp>

#include <stdexcept>

#include <limits>
#include <random>

#include "frame_blocks.hpp"
#include "frame_records.hpp"
#include "message_builders.hpp"
#include "wire_limits.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
using ocean::Tick;

namespace {

using ocean::kLargestTick;

struct Decoded {
  Bytes block;                      // the records' payloads view it (a moved vector keeps its buffer)
  std::vector<FrameRecord> records;
};

// Encodes and decodes, requires success, and checks the records come back exactly and view the block.
Decoded round_trip(std::span<const FrameRecord> records) {
  Bytes block = encode_frame_block(records);
  std::vector<FrameRecord> out;
  const FrameBlockResult parsed = decode_frame_block(block, out);
  INFO(parsed.rule);
  REQUIRE(parsed);
  CHECK(parsed.reason == Reason::ok);
  CHECK(parsed.rule.empty());
  CHECK(same_records(out, records));
  for (const FrameRecord& r : out)
    if (!r.payload.empty()) {
      CHECK(r.payload.data() >= block.data());
      CHECK(r.payload.data() + r.payload.size() <= block.data() + block.size());
    }
  // Through a frames datagram too.
  const Bytes datagram = frames_datagram(records);
  REQUIRE(datagram.size() == block.size() + 1);
  CHECK(datagram[0] == static_cast<std::uint8_t>(DatagramKind::frames));
  CHECK(std::equal(block.begin(), block.end(), datagram.begin() + 1));
  return Decoded{std::move(block), std::move(out)};
}

// Requires decode_frame_block to refuse `block` for `reason`, leaving a non-empty `out` empty.
void expect_refused(const Bytes& block, Reason reason) {
  const Bytes other(3, 1);
  std::vector<FrameRecord> out{FrameRecord{7, 7, true, 0, 1, other}};
  const FrameBlockResult parsed = decode_frame_block(block, out);
  INFO("rule: " << parsed.rule);
  CHECK_FALSE(parsed);
  CHECK(parsed.reason == reason);
  CHECK_FALSE(parsed.rule.empty());
  CHECK(out.empty());
}

Bytes ten_byte_varint(std::uint8_t last) {
  Bytes v(9, 0x80);
  v.push_back(last);
  return v;
}

}  // namespace

TEST_CASE("frame block layout: newest tick, then per record offset, lag, count - 1, index, length, payload") {
  const Bytes key_payload{0xAA, 0xBB}, delta_payload{0xCC};
  const std::vector<FrameRecord> records{FrameRecord{300, 300, true, 0, 1, key_payload},
                                         FrameRecord{298, 290, false, 1, 3, delta_payload}};
  const Bytes block = encode_frame_block(records);
  CHECK(block == Bytes{0xAC, 0x02,                          // newest tick 300
                       0x00, 0x00, 0x00, 0x02, 0xAA, 0xBB,  // tick 300, key, one chunk (no index), 2 bytes
                       0x02, 0x08, 0x02, 0x01, 0x01, 0xCC}); // tick 298, lag 8, chunk 1 of 3, 1 byte
  CHECK(frames_datagram(records) == Bytes{0x01, 0xAC, 0x02, 0x00, 0x00, 0x00, 0x02, 0xAA, 0xBB, 0x02, 0x08, 0x02,
                                          0x01, 0x01, 0xCC});
  round_trip(records);

  const Bytes message = encode(Ping{5, Bytes(8, 1), 1, 2});
  const Bytes datagram = message_datagram(message);
  REQUIRE(datagram.size() == message.size() + 1);
  CHECK(datagram[0] == static_cast<std::uint8_t>(DatagramKind::message));
  CHECK(std::equal(message.begin(), message.end(), datagram.begin() + 1));

  CHECK(encode_frame_block({}).empty());
}

TEST_CASE("frame records round-trip: keys, deltas, several records in any order") {
  const Bytes a(40, 1), b(1, 2), c(0, 0), d(300, 4);
  round_trip(std::vector<FrameRecord>{FrameRecord{0, 0, true, 0, 1, a}});  // tick 0
  round_trip(std::vector<FrameRecord>{FrameRecord{1, 0, false, 0, 1, b}});  // a delta from tick 0
  round_trip(std::vector<FrameRecord>{FrameRecord{77, 77, true, 0, 1, c}});  // an empty payload
  // Oldest first as the server sends them, and out of order: newest is the largest tick wherever it is.
  const std::vector<FrameRecord> mixed{FrameRecord{4995, 4994, false, 0, 1, b}, FrameRecord{4996, 4996, true, 0, 1, a},
                                       FrameRecord{5000, 4996, false, 0, 1, d}, FrameRecord{4998, 4990, false, 0, 1, c},
                                       FrameRecord{4999, 4999 - kMaxFrameLag, false, 0, 1, a}};
  const Decoded out = round_trip(mixed);
  CHECK(out.records.at(3).tick == 4998);
  CHECK(out.block.at(0) == ((5000 & 0x7F) | 0x80));  // newest: 5000, though not the last record
  // The most records a block may hold.
  std::vector<FrameRecord> full;
  for (Tick t = 0; t < kMaxRecordsPerBlock; ++t) full.push_back(FrameRecord{5000 + t, 5000, t == 0, 0, 1, b});
  round_trip(full);
}

TEST_CASE("frame records round-trip at ticks near 2^32, 2^63 and the end of the range") {
  const Bytes p(13, 0x3C);
  for (Tick base : {Tick{0xFFFF'FFFFu} - 3, Tick{0x1'0000'0000u}, (Tick{1} << 63) - 2, Tick{1} << 63,
                    kLargestTick - 5}) {
    INFO("base " << base);
    const std::vector<FrameRecord> records{FrameRecord{base, base, true, 0, 1, p},
                                           FrameRecord{base + 1, base, false, 0, 2, p},
                                           FrameRecord{base + 1, base, false, 1, 2, p},
                                           FrameRecord{base + 5, base + 5 - kMaxFrameLag, false, 0, 1, p}};
    round_trip(records);
  }
  // The largest tick is a 10-byte varint whose last byte carries the top bit only.
  const FrameRecord top{kLargestTick, kLargestTick, true, 0, 1, p};
  const Bytes block = encode_frame_block(std::span(&top, 1));
  CHECK(Bytes(block.begin(), block.begin() + 10) == [] { Bytes v(9, 0xFF); v.push_back(0x01); return v; }());
  round_trip(std::span(&top, 1));
  // 2^63 exactly: nine continuation bytes, then 0x01.
  Bytes exact = ten_byte_varint(0x01);
  RawBlock rest;
  rest.record(0, 0);
  exact.insert(exact.end(), rest.bytes.begin(), rest.bytes.end());
  std::vector<FrameRecord> out;
  REQUIRE(decode_frame_block(exact, out));
  CHECK(out.at(0).tick == Tick{1} << 63);
}

TEST_CASE("frame records round-trip: a frame in many chunks") {
  Bytes payload(5000);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 13 + 1);
  std::vector<FrameRecord> chunks;
  for (std::uint16_t i = 0; i < 10; ++i)
    chunks.push_back(FrameRecord{4'294'967'300ull, 4'294'967'290ull, false, i, 10, std::span(payload).subspan(i * 500u, 500)});
  const Decoded out = round_trip(chunks);
  Bytes joined;
  for (const FrameRecord& r : out.records) joined.insert(joined.end(), r.payload.begin(), r.payload.end());
  CHECK(joined == payload);
  // The widest chunk numbers.
  const Bytes small{1, 2};
  round_trip(std::vector<FrameRecord>{FrameRecord{9, 9, true, 0, kMaxChunksPerFrame, small},
                                      FrameRecord{9, 9, true, kMaxChunksPerFrame - 1, kMaxChunksPerFrame, small}});
}

TEST_CASE("kMaxRecordOverheadBytes bounds what a record adds besides its payload") {
  const Bytes payload(70000, 9);
  // A record far behind the newest (a 10-byte offset), the largest lag, count and index.
  const std::vector<FrameRecord> records{
      FrameRecord{kLargestTick, kLargestTick, true, 0, 1, std::span(payload).first(0)},
      FrameRecord{kMaxFrameLag, 0, false, kMaxChunksPerFrame - 1, kMaxChunksPerFrame, payload}};
  const Bytes block = encode_frame_block(records);
  const std::size_t newest_and_first = 10 + 4;  // newest (10), then 0, 0, 0, 0
  CHECK(block.size() - newest_and_first - payload.size() <= kMaxRecordOverheadBytes);
  round_trip(records);
}

TEST_CASE("decode_frame_block: empty blocks and truncated varints are refused") {
  expect_refused({}, Reason::empty);
  expect_refused(RawBlock().v(1000).bytes, Reason::empty);  // a newest tick and no record
  expect_refused({0x80}, Reason::truncated);                 // newest tick cut short
  expect_refused({0xFF, 0xFF}, Reason::truncated);
  // An 11-byte varint, and a tenth byte that would overflow 64 bits.
  Bytes eleven(10, 0xFF);
  eleven.push_back(0x01);
  expect_refused(eleven, Reason::truncated);
  Bytes overflow = ten_byte_varint(0x02);
  overflow.insert(overflow.end(), {0, 0, 0, 0});
  expect_refused(overflow, Reason::truncated);
  // The same inside a record: its tick offset.
  Bytes in_record = RawBlock().v(1000).bytes;
  in_record.insert(in_record.end(), eleven.begin(), eleven.end());
  expect_refused(in_record, Reason::truncated);
  // Record headers cut after each field.
  expect_refused(RawBlock().v(1000).v(0).bytes, Reason::truncated);                  // no lag
  expect_refused(RawBlock().v(1000).v(0).v(1).bytes, Reason::truncated);             // no count
  expect_refused(RawBlock().v(1000).v(0).v(1).raw({0x80}).bytes, Reason::truncated); // count cut short
  expect_refused(RawBlock().v(1000).v(0).v(1).v(1).bytes, Reason::truncated);        // count 2: no index
  expect_refused(RawBlock().v(1000).v(0).v(1).v(0).bytes, Reason::truncated);        // no length
  expect_refused(RawBlock().v(1000).v(0).v(1).v(1).v(1).bytes, Reason::truncated);   // index, no length
}

TEST_CASE("decode_frame_block: a payload past the end of the block is refused") {
  expect_refused(RawBlock().v(1000).v(0).v(0).v(0).v(5).payload(4).bytes, Reason::truncated);
  expect_refused(RawBlock().v(1000).v(0).v(0).v(0).v(kLargestTick).payload(4).bytes, Reason::truncated);
  expect_refused(RawBlock().v(1000).record(0, 0).v(1).v(0).v(0).v(100).payload(99).bytes, Reason::truncated);
  std::vector<FrameRecord> out;  // exactly to the end is fine
  REQUIRE(decode_frame_block(RawBlock().v(1000).v(0).v(0).v(0).v(5).payload(5).bytes, out));
  CHECK(out.at(0).payload.size() == 5);
}

TEST_CASE("decode_frame_block: ticks and lags out of range are refused") {
  expect_refused(RawBlock().v(1000).record(1001, 0).bytes, Reason::bad_sequence);                // back > newest
  expect_refused(RawBlock().v(kLargestTick - 1).record(kLargestTick, 0).bytes, Reason::bad_sequence);
  expect_refused(RawBlock().v(5000).record(0, kMaxFrameLag + 1).bytes, Reason::bad_sequence);   // lag > 1024
  expect_refused(RawBlock().v(5000).record(0, kLargestTick).bytes, Reason::bad_sequence);
  expect_refused(RawBlock().v(100).record(0, 101).bytes, Reason::bad_sequence);                // lag > tick
  expect_refused(RawBlock().v(100).record(50, 51).bytes, Reason::bad_sequence);
  std::vector<FrameRecord> out;
  REQUIRE(decode_frame_block(RawBlock().v(100).record(50, 50).record(0, 100).bytes, out));  // lag == tick: baseline 0
  CHECK(out.at(0).baseline == 0);
  CHECK(out.at(1).baseline == 0);
  REQUIRE(decode_frame_block(RawBlock().v(5000).record(0, kMaxFrameLag).bytes, out));
  CHECK(out.at(0).baseline == 5000 - kMaxFrameLag);
}

TEST_CASE("decode_frame_block: counts and indexes out of range are refused") {
  const auto chunk = [](std::uint64_t count_minus_1, std::uint64_t index) {
    return RawBlock().v(1000).v(0).v(0).v(count_minus_1).v(index).v(2).payload(2).bytes;
  };
  expect_refused(chunk(kMaxChunksPerFrame, 0), Reason::bad_chunk_index);        // count 4097
  expect_refused(chunk(Tick{1} << 40, 0), Reason::bad_chunk_index);              // huge
  expect_refused(chunk(kLargestTick, 0), Reason::bad_chunk_index);               // count 0 (count - 1 wrapped, 64-bit)
  expect_refused(chunk(0xFFFF'FFFFu, 0), Reason::bad_chunk_index);               // count 0 (count - 1 wrapped, 32-bit)
  expect_refused(chunk(4, 5), Reason::bad_chunk_index);                          // index 5 of 5
  expect_refused(chunk(4, 6), Reason::bad_chunk_index);
  expect_refused(chunk(kMaxChunksPerFrame - 1, kMaxChunksPerFrame), Reason::bad_chunk_index);
  expect_refused(chunk(1, Tick{1} << 40), Reason::bad_chunk_index);
  // The encoder refuses to write such records at all.
  const Bytes p{1};
  const FrameRecord zero{10, 10, true, 0, 0, p};
  CHECK_THROWS_AS(encode_frame_block(std::span(&zero, 1)), std::invalid_argument);
  const FrameRecord past{10, 10, true, 3, 3, p};
  CHECK_THROWS_AS(encode_frame_block(std::span(&past, 1)), std::invalid_argument);
  const FrameRecord self_delta{10, 10, false, 0, 1, p};
  CHECK_THROWS_AS(encode_frame_block(std::span(&self_delta, 1)), std::invalid_argument);
}

TEST_CASE("decode_frame_block: more than 64 records are refused") {
  RawBlock block;
  block.v(1000);
  for (std::size_t i = 0; i < kMaxRecordsPerBlock; ++i) block.record(i, 0, 1);
  std::vector<FrameRecord> out;
  REQUIRE(decode_frame_block(block.bytes, out));
  CHECK(out.size() == kMaxRecordsPerBlock);
  block.record(kMaxRecordsPerBlock, 0, 1);
  expect_refused(block.bytes, Reason::out_of_range);
  // Even 65 empty records.
  RawBlock empties;
  empties.v(0);
  for (std::size_t i = 0; i <= kMaxRecordsPerBlock; ++i) empties.record(0, 0, 0);
  expect_refused(empties.bytes, Reason::out_of_range);
}

TEST_CASE("decode_frame_block: a bad record after good ones refuses the whole block") {
  RawBlock block;
  block.v(1000).record(2, 1).record(1, 1);
  std::vector<FrameRecord> out;
  REQUIRE(decode_frame_block(block.bytes, out));
  REQUIRE(out.size() == 2);
  const std::pair<Bytes, Reason> bad_third[] = {
      {RawBlock(block).record(0, 2000).bytes, Reason::bad_sequence},
      {RawBlock(block).v(0).v(0).v(9).v(10).v(1).payload(1).bytes, Reason::bad_chunk_index},
      {RawBlock(block).raw({0x80}).bytes, Reason::truncated},
      {RawBlock(block).v(0).v(0).v(0).v(3).bytes, Reason::truncated},
      {RawBlock(block).v(1001).v(0).v(0).v(0).bytes, Reason::bad_sequence}};
  for (const auto& [bad, reason] : bad_third) expect_refused(bad, reason);
}

TEST_CASE("random and mutated blocks never crash, and what decodes is sound") {
  std::mt19937_64 rng(1234);
  std::uniform_int_distribution<int> byte(0, 255);
  const Bytes a(30, 7), b(3, 8);
  const std::vector<FrameRecord> valid{FrameRecord{70000, 69990, false, 1, 3, a}, FrameRecord{70001, 70001, true, 0, 1, b},
                                       FrameRecord{70002, 70001, false, 0, 1, a}};
  const Bytes original = encode_frame_block(valid);
  std::size_t ok = 0, refused = 0;
  for (int round = 0; round < 20000; ++round) {
    Bytes bytes;
    if (round % 2 == 0) {
      bytes.resize(std::uniform_int_distribution<std::size_t>(0, 80)(rng));
      for (auto& x : bytes) x = static_cast<std::uint8_t>(byte(rng));
    } else {
      bytes = original;
      const int flips = 1 + round % 4;
      for (int f = 0; f < flips; ++f)
        bytes[std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(rng)] = static_cast<std::uint8_t>(byte(rng));
      if (round % 7 == 1) bytes.resize(std::uniform_int_distribution<std::size_t>(0, bytes.size())(rng));
    }
    std::vector<FrameRecord> out;
    const FrameBlockResult parsed = decode_frame_block(bytes, out);
    if (!parsed) {
      ++refused;
      REQUIRE(out.empty());
      REQUIRE_FALSE(parsed.rule.empty());
      continue;
    }
    ++ok;
    REQUIRE(!out.empty());
    REQUIRE(out.size() <= kMaxRecordsPerBlock);
    for (const FrameRecord& r : out) {
      REQUIRE(r.count >= 1);
      REQUIRE(r.count <= kMaxChunksPerFrame);
      REQUIRE(r.index < r.count);
      REQUIRE(r.baseline <= r.tick);
      REQUIRE(r.tick - r.baseline <= kMaxFrameLag);
      REQUIRE(r.key == (r.baseline == r.tick));
      if (!r.payload.empty()) {
        REQUIRE(r.payload.data() >= bytes.data());
        REQUIRE(r.payload.data() + r.payload.size() <= bytes.data() + bytes.size());
      }
    }
    // Re-encoding gives the same records, in no more bytes (the encoder writes the shortest form).
    const Bytes again = encode_frame_block(out);
    REQUIRE(again.size() <= bytes.size());
    std::vector<FrameRecord> second;
    REQUIRE(decode_frame_block(again, second));
    REQUIRE(same_records(second, out));
  }
  CHECK(ok > 0);
  CHECK(refused > ok);
}
