// Every class of malformed chunk is refused with its reason, and the decoder is left exactly as it
// was (same complete states, same frame on show).
#include "range_coder.hpp"
#include "state_hash.hpp"
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace ocean::codec;
using namespace ocean::codec::test;
namespace model = ocean::model;

namespace {

struct Snapshot {
  std::vector<ocean::Tick> ticks;
  std::vector<std::uint64_t> hashes;
  ocean::Tick shown_tick = 0;
  std::vector<float> shown;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(Decoder& d) {
  Snapshot s;
  s.ticks = d.complete_ticks();
  for (ocean::Tick t : s.ticks) s.hashes.push_back(hash_state(*d.state(t)));
  if (const ReconstructedFrame* r = d.latest()) {
    s.shown_tick = r->tick;
    s.shown = r->height;
  }
  return s;
}

// A stream with ticks 1 (key) .. 5 complete, and frame 6 (several chunks) ready but not sent.
constexpr int kGridLog2 = 5;

struct Fixture {
  StreamConfig config = test_config(32, 30);
  SyntheticOcean ocean{32, 256.0, 100, 77, 0.5};
  Encoder enc = test_encoder(config, options());
  Decoder dec = test_decoder(config, decoder_options());
  std::shared_ptr<const EncodedFrame> next;

  static EncoderOptions options() {
    EncoderOptions o;
    o.key_precision_bits = 0;
    o.key_velocity_extra_bits = 0;
    o.max_payload = 100;
    return o;
  }
  static DecoderOptions decoder_options() {
    DecoderOptions o;
    o.max_payload = 120;  // room for rebuilt chunks whose header grew
    o.max_lag = 8;
    o.history_ticks = 16;
    return o;
  }
  Fixture() {
    for (ocean::Tick t = 0; t <= 6; ++t) enc.add_truth(t, view_of(ocean.at(t / 30.0)));
    auto f = enc.encode_key(1);
    for (const Chunk& c : f->chunks) REQUIRE(dec.accept(c) == ChunkError::ok);
    for (ocean::Tick t = 2; t <= 5; ++t) {
      f = enc.encode_delta(t, f->id);
      for (const Chunk& c : f->chunks) REQUIRE(dec.accept(c) == ChunkError::ok);
    }
    next = enc.encode_delta(6, f->id);
    REQUIRE(next->chunks.size() >= 3);
  }

  // Rewrites a chunk's payload from a (modified) header, envelope and body, with a valid CRC.
  static Chunk rebuild(const Chunk& c, const std::function<void(ChunkHeader&, Chunk&)>& edit,
                       std::vector<std::uint8_t> body = {}, bool keep_body = true) {
    ChunkHeader h;
    std::span<const std::uint8_t> b;
    REQUIRE(parse_payload(view(c), 65536, kGridLog2, h, b) == ChunkError::ok);
    Chunk out = c;
    edit(h, out);
    if (keep_body) body.assign(b.begin(), b.end());
    out.payload = write_payload(h, view(out), kGridLog2, body);
    return out;
  }

  void expect(const Chunk& c, ChunkError reason) {
    const Snapshot before = snapshot(dec);
    CHECK(to_string(dec.accept(c)) == to_string(reason));
    CHECK(snapshot(dec) == before);
  }
};

}  // namespace

TEST_CASE("malformed chunks are refused with their reason and change nothing") {
  Fixture fx;
  const Chunk good = fx.next->chunks[0];

  SECTION("truncated") {
    Chunk c = good;
    c.payload.resize(c.payload.size() / 2);  // the body has no length: a cut one fails the CRC
    fx.expect(c, ChunkError::checksum_mismatch);
    c.payload.resize(5);  // the range varints end early
    fx.expect(c, ChunkError::truncated);
    c.payload.resize(2);
    fx.expect(c, ChunkError::truncated);
    c.payload.clear();
    fx.expect(c, ChunkError::truncated);
  }
  SECTION("oversized") {
    Chunk c = good;
    c.payload.resize(121, 0);
    fx.expect(c, ChunkError::oversized);
  }
  SECTION("bad flags") {
    // Every flag bit has a meaning since codec version 6 (bit 7: the stream has a wake): a flipped
    // one is caught by the CRC.
    Chunk c = good;
    c.payload[0] |= 0x80;
    fx.expect(c, ChunkError::checksum_mismatch);
    c = good;
    c.key = true;  // envelope says key, payload says delta
    fx.expect(c, ChunkError::bad_flags);
  }
  SECTION("wrong dimensions") {
    // The grid is bound by the CRC: a chunk of another grid fails it.
    Chunk other = good;
    ChunkHeader h;
    std::span<const std::uint8_t> b;
    REQUIRE(parse_payload(view(good), 65536, kGridLog2, h, b) == ChunkError::ok);
    other.payload = write_payload(h, view(good), kGridLog2 + 1, std::vector<std::uint8_t>(b.begin(), b.end()));
    fx.expect(other, ChunkError::checksum_mismatch);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader& h, Chunk&) { h.normals = false; }), ChunkError::wrong_dimensions);
  }
  SECTION("unknown scene") {
    fx.expect(Fixture::rebuild(good, [](ChunkHeader& h, Chunk&) { h.scene_tag = 1; }), ChunkError::unknown_scene);
  }
  SECTION("bad range / offsets") {
    fx.expect(Fixture::rebuild(good, [](ChunkHeader& h, Chunk&) { h.item_end = 32 * 32 + 1; }), ChunkError::bad_range);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader& h, Chunk&) { h.item_begin = h.item_end; }), ChunkError::bad_range);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader& h, Chunk&) { h.item_begin = 5000; h.item_end = 4000; }),
              ChunkError::bad_range);
  }
  SECTION("checksum") {
    Chunk c = good;
    c.payload.back() ^= 0x5A;
    fx.expect(c, ChunkError::checksum_mismatch);
    c = good;
    c.tick += 1;  // the CRC covers the envelope too
    fx.expect(c, ChunkError::checksum_mismatch);
  }
  SECTION("bad index") {
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.index = c.count; }), ChunkError::bad_index);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.count = 0; c.index = 0; }), ChunkError::bad_index);
  }
  SECTION("bad value in the body") {
    RangeEncoder rc;
    UIntModel m;
    for (int i = 0; i <= UIntModel::kMaxBits; ++i) rc.encode_bit(m.length[i], 1);  // overlong count
    const auto body = rc.finish();
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk&) {}, body, false), ChunkError::bad_value);
  }
  SECTION("baselines and lags") {
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.baseline = c.tick; }), ChunkError::bad_baseline);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.baseline = 0; c.tick = 20; }),
              ChunkError::lag_too_large);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.baseline = 0; }), ChunkError::unknown_baseline);
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.tick = 3; c.baseline = 2; }),
              ChunkError::duplicate_chunk);  // tick 3 is already complete
  }
  SECTION("frame consistency, duplicates, overlaps, coverage") {
    REQUIRE(fx.dec.accept(good) == ChunkError::ok);
    fx.expect(good, ChunkError::duplicate_chunk);
    const Chunk second = fx.next->chunks[1];
    fx.expect(Fixture::rebuild(second, [](ChunkHeader&, Chunk& c) { c.count += 1; }), ChunkError::inconsistent_frame);
    fx.expect(Fixture::rebuild(second, [](ChunkHeader&, Chunk& c) { c.baseline -= 1; }), ChunkError::inconsistent_frame);
    const std::uint32_t first_end = [&] {
      ChunkHeader h;
      std::span<const std::uint8_t> b;
      REQUIRE(parse_payload(view(good), 1000, kGridLog2, h, b) == ChunkError::ok);
      return h.item_end;
    }();
    fx.expect(Fixture::rebuild(second, [&](ChunkHeader& h, Chunk&) { h.item_begin = first_end - 1; }),
              ChunkError::overlapping_range);
    // All but the last chunk arrive; a last chunk that leaves a hole is refused.
    for (std::size_t i = 1; i + 1 < fx.next->chunks.size(); ++i) REQUIRE(fx.dec.accept(fx.next->chunks[i]) == ChunkError::ok);
    const Chunk last = fx.next->chunks.back();
    fx.expect(Fixture::rebuild(last, [](ChunkHeader& h, Chunk&) { h.item_end -= 1; }), ChunkError::coverage_mismatch);
    REQUIRE(fx.dec.accept(last) == ChunkError::ok);
    CHECK(fx.dec.is_complete(6));
  }
  SECTION("stale tick") {
    // Advance the decoder far beyond history, then replay an old frame's chunk.
    for (ocean::Tick t = 7; t <= 30; ++t) fx.enc.add_truth(t, view_of(fx.ocean.at(t / 30.0)));
    for (const Chunk& c : fx.next->chunks) REQUIRE(fx.dec.accept(c) == ChunkError::ok);
    auto f = fx.next;
    for (ocean::Tick t = 7; t <= 30; ++t) {
      f = fx.enc.encode_delta(t, f->id);
      for (const Chunk& c : f->chunks) REQUIRE(fx.dec.accept(c) == ChunkError::ok);
    }
    fx.expect(Fixture::rebuild(good, [](ChunkHeader&, Chunk& c) { c.tick = 2; c.baseline = 1; }), ChunkError::stale_tick);
  }
  SECTION("random bytes") {
    std::mt19937_64 rng(123);
    for (int i = 0; i < 3000; ++i) {
      Chunk c = good;
      c.payload.resize(rng() % 100);
      for (auto& b : c.payload) b = static_cast<std::uint8_t>(rng());
      if (i % 2 && !c.payload.empty()) c.payload[0] &= 0x0F;  // get past the flags check
      const Snapshot before = snapshot(fx.dec);
      REQUIRE(fx.dec.accept(c) != ChunkError::ok);
      REQUIRE(snapshot(fx.dec) == before);
    }
  }
}

TEST_CASE("a scene that does not describe the stream refuses its chunks and changes nothing") {
  Fixture fx;
  // From tick 6 on the decoder is told of a scene of another patch: its model cannot be built.
  model::SceneParams wrong = test_scene(fx.config);
  wrong.patch_x_m = 100.0;
  fx.dec.add_scene(6, 0, wrong);
  fx.expect(fx.next->chunks[0], ChunkError::unknown_scene);
  fx.expect(fx.next->chunks[0], ChunkError::unknown_scene);  // and again: nothing was half-built
}
