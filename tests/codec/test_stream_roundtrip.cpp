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
