// libFuzzer harness for the codec's chunk decoder (Decoder::accept, the reader of frame record
// payloads). Input: a mode byte, then records of [21-byte envelope | payload] (record_format.hpp,
// codec_stream.hpp). Mode bit 0: start from a decoder primed with a real key + deltas (ticks 1..3)
// instead of a fresh one (the key path from scratch); both know the stream's scene from tick 0.
// Record tag bit 0: recompute the chunk CRC, so mutations reach the body decoder instead of
// stopping at checksum_mismatch.
// Invariants: a refused chunk leaves the decoder exactly as it was (complete states by hash, the
// frame on show); an accepted chunk is refused when repeated; a shown frame has grid^2 finite samples.
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "codec_stream.hpp"
#include "fuzz_check.hpp"
#include "record_format.hpp"
#include "state_hash.hpp"

using namespace ocean;

namespace {

struct DecoderSnapshot {
  std::vector<Tick> ticks;
  std::vector<std::uint64_t> hashes;
  std::optional<Tick> shown_tick;
  std::vector<float> shown_height;
  bool operator==(const DecoderSnapshot&) const = default;
};

DecoderSnapshot snapshot(codec::Decoder& d) {
  DecoderSnapshot s;
  s.ticks = d.complete_ticks();
  for (Tick t : s.ticks) s.hashes.push_back(codec::hash_state(*d.state(t)));
  if (const codec::ReconstructedFrame* f = d.latest()) {
    s.shown_tick = f->tick;
    s.shown_height = f->height;
  }
  return s;
}

// A decoder that took a real key and two deltas (ticks 1..3). codec::Decoder is move-only (its
// SceneTimeline is), so each input gets a fresh one fed the same cached chunks.
codec::Decoder primed_decoder() {
  static const auto stream = fuzz::make_codec_stream(3);
  codec::Decoder d = fuzz::codec_stream_decoder();
  for (const auto& frame : stream)
    for (const codec::Chunk& c : frame->chunks) FUZZ_REQUIRE(d.accept(c) == codec::ChunkError::ok);
  FUZZ_REQUIRE(d.newest_complete() == Tick{3});
  return d;
}

// The CRC covers a pseudo header - the envelope with 64-bit ticks and the stream's grid_log2 - and
// the payload without its CRC field (CODEC.md 5; chunk_crc() in chunk_format.cpp).
void fix_crc(const codec::ChunkView& envelope, int grid_log2, std::vector<std::uint8_t>& payload) {
  constexpr std::size_t kCrcOffset = 1;
  if (payload.size() < kCrcOffset + 2) return;
  std::uint8_t pseudo[22];
  for (int i = 0; i < 8; ++i) pseudo[i] = static_cast<std::uint8_t>(envelope.tick >> (8 * i));
  for (int i = 0; i < 8; ++i) pseudo[8 + i] = static_cast<std::uint8_t>(envelope.baseline >> (8 * i));
  pseudo[16] = envelope.key ? 1 : 0;
  pseudo[17] = static_cast<std::uint8_t>(envelope.index);
  pseudo[18] = static_cast<std::uint8_t>(envelope.index >> 8);
  pseudo[19] = static_cast<std::uint8_t>(envelope.count);
  pseudo[20] = static_cast<std::uint8_t>(envelope.count >> 8);
  pseudo[21] = static_cast<std::uint8_t>(grid_log2);
  const std::span<const std::uint8_t> p(payload);
  std::uint16_t crc = codec::crc16_ccitt(0xFFFF, pseudo);
  crc = codec::crc16_ccitt(crc, p.first(kCrcOffset));
  crc = codec::crc16_ccitt(crc, p.subspan(kCrcOffset + 2));
  payload[kCrcOffset] = static_cast<std::uint8_t>(crc);
  payload[kCrcOffset + 1] = static_cast<std::uint8_t>(crc >> 8);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in({data, size});
  const bool primed = (in.take<std::uint8_t>() & 1) != 0;
  codec::Decoder decoder = primed ? primed_decoder() : fuzz::codec_stream_decoder();
  const std::size_t samples = std::size_t{decoder.config().grid} * decoder.config().grid;
  const int grid_log2 = decoder.config().grid_log2();

  fuzz::Record record;
  for (int n = 0; n < 64 && fuzz::next_record(in, record); ++n) {
    codec::ChunkView chunk = fuzz::chunk_view_of(record.bytes);
    std::vector<std::uint8_t> payload(chunk.payload.begin(), chunk.payload.end());
    if (record.tag & 1) fix_crc(chunk, grid_log2, payload);
    chunk.payload = payload;

    const DecoderSnapshot before = snapshot(decoder);
    const codec::ChunkError error = decoder.accept(chunk);
    if (error != codec::ChunkError::ok) {
      FUZZ_REQUIRE(snapshot(decoder) == before);
      continue;
    }
    const DecoderSnapshot after = snapshot(decoder);
    FUZZ_REQUIRE(decoder.accept(chunk) != codec::ChunkError::ok);
    FUZZ_REQUIRE(snapshot(decoder) == after);
    if (const codec::ReconstructedFrame* f = decoder.latest()) {
      FUZZ_REQUIRE(f->height.size() == samples);
      for (float h : f->height) FUZZ_REQUIRE(std::isfinite(h));
    }
  }
  return 0;
}
