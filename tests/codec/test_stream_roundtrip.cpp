// Closed loop on a perfect link: the decoder reproduces the encoder's reconstruction bit for bit,
// every sample of every frame stays within step / 2 (heights) and slope_step / 2 (slopes), for
// baseline lags 1 and 4, with fine keys (few corrections) and coarse keys (many, multi-chunk).
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace ocean::codec;
using namespace ocean::codec::test;

namespace {

void check_run(const RunStats& st, const StreamConfig& c, int frames) {
  CHECK(st.frames == frames);
  CHECK(st.complete_frames == frames);
  CHECK(st.rejected == 0);
  CHECK(st.bitwise);
  CHECK(st.states_equal);
  CHECK(st.max_height_err <= 0.5 * double(c.height_step_m));
  if (c.normals) CHECK(st.max_slope_err <= 0.5 * double(c.slope_step));
}

}  // namespace

TEST_CASE("lite-size stream stays within the bound for thousands of frames at lags 1 and 4") {
  const StreamConfig c = test_config(32, 15);
  const SyntheticOcean ocean(32, 256.0, 120, 11);
  for (std::uint32_t lag : {1u, 4u}) {
    const int frames = 2500;
    const RunStats st = run_stream(ocean, c, {}, frames, lag);
    INFO("lag " << lag << " delta bytes/frame " << double(st.delta_bytes) / frames << " corrections " << st.corrections);
    check_run(st, c, frames);
    CHECK(st.key_bytes > 0);
  }
}

TEST_CASE("mobile-size stream with coarse keys: many corrections, many chunks, still exact") {
  StreamConfig c = test_config(64, 30);
  const SyntheticOcean ocean(64, 256.0, 150, 5, 0.5);
  EncoderOptions o;
  o.key_precision_bits = 0;        // key error ~ a whole step: corrections every frame
  o.key_velocity_extra_bits = 0;
  o.max_payload = 200;
  for (std::uint32_t lag : {1u, 4u}) {
    const int frames = 150;
    const RunStats st = run_stream(ocean, c, o, frames, lag);
    INFO("lag " << lag << " corrections " << st.corrections << " chunks " << st.delta_chunks);
    check_run(st, c, frames);
    CHECK(st.corrections > 500);
    CHECK(st.delta_chunks > std::size_t(frames));  // frames really were split
  }
}

TEST_CASE("heights-only stream with finite depth") {
  StreamConfig c = test_config(32, 30, false);
  c.depth_m = 8.0;
  const SyntheticOcean ocean(32, 128.0, 150, 3, 0.3, 8.0);
  c.patch_x_m = c.patch_z_m = 128.0;
  const RunStats st = run_stream(ocean, c, {}, 1500, 2);
  check_run(st, c, 1500);
}

// The encoder keeps each baseline's state as advanced for its last delta and corrects each
// distinct prediction of a tick once; neither may change a byte. An encoder that encodes a delta
// from the key at every tick (and from a second baseline at the same ticks) must send the very
// bytes a fresh encoder sends when it encodes only the last one.
TEST_CASE("encoder caches leave every byte as a fresh encoder makes it") {
  const StreamConfig c = test_config(64, 30);
  const SyntheticOcean ocean(64, 256.0, 200, 23);
  const double dt = 1.0 / c.rate_hz;
  Encoder stepped = test_encoder(c), fresh = test_encoder(c);
  for (Encoder* e : {&stepped, &fresh}) e->add_truth(0, view_of(ocean.at(0.0)));
  const StateId key = stepped.encode_key(0)->id;
  REQUIRE(fresh.encode_key(0)->id == key);
  constexpr ocean::Tick kLast = 12;
  StateId second{};
  for (ocean::Tick t = 1; t <= kLast; ++t) {
    for (Encoder* e : {&stepped, &fresh}) e->add_truth(t, view_of(ocean.at(t * dt)));
    if (t < kLast) {
      const auto delta = stepped.encode_delta(t, key);
      if (t == 3) second = delta->id;
      if (t > 3) stepped.encode_delta(t, second);  // a second baseline at the same ticks
    }
  }
  // The fresh encoder makes the second baseline in one step (advanced 0 -> 3, not 0 -> 1 -> 2 -> 3).
  const StateId fresh_second = fresh.encode_delta(3, key)->id;
  REQUIRE(*fresh.state(fresh_second) == *stepped.state(second));
  for (const auto& [from_stepped, from_fresh] : {std::pair{key, key}, std::pair{second, fresh_second}}) {
    const auto a = stepped.encode_delta(kLast, from_stepped);
    const auto b = fresh.encode_delta(kLast, from_fresh);
    REQUIRE(a->chunks.size() == b->chunks.size());
    for (std::size_t i = 0; i < a->chunks.size(); ++i) CHECK(a->chunks[i].payload == b->chunks[i].payload);
    CHECK(a->reconstruction.height == b->reconstruction.height);
    CHECK(*stepped.state(a->id) == *fresh.state(b->id));
    CHECK(a->stats.corrections_height > 0);  // the synthetic sea is not the scene: corrections are exercised
  }
}
