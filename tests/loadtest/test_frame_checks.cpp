// The ground-truth checker and the on-time classification on real sim frames.
#include <catch2/catch.hpp>

#include "client_tally.hpp"
#include "frame_verdict.hpp"
#include "ground_truth.hpp"
#include "stream_facts.hpp"

using namespace ocean::loadtest;

namespace {

ocean::protocol::SceneParams small_scene(double wind = 10.0) {
  ocean::protocol::SceneParams s;
  s.size_x = s.size_z = 64;
  s.patch_x_m = s.patch_z_m = 64.0;
  s.wind_speed_mps = wind;
  return s;
}

}  // namespace

TEST_CASE("ground truth: one evaluation per (tick, grid), shared by every caller") {
  GroundTruth truth(30);
  truth.set_scene(0, small_scene());
  const ocean::sim::Frame a = *truth.at(900, 32);
  truth.at(900, 32);
  CHECK(truth.evaluations() == 1);
  const ocean::sim::Frame& b = *truth.at(901, 32);
  CHECK(truth.evaluations() == 2);
  REQUIRE(a.height.size() == 32u * 32u);
  CHECK(a.slope_x.size() == a.height.size());
  CHECK(a.height != b.height);  // the sea moves between ticks
  CHECK(truth.time_of(901) == Approx(30.0 + 1.0 / 30.0));
}

TEST_CASE("ground truth: a scene change applies from its effective tick only") {
  GroundTruth truth(30);
  truth.set_scene(0, small_scene(10.0));
  const ocean::sim::Frame before = *truth.at(100, 32);
  const ocean::sim::Frame old_after = *truth.at(200, 32);
  truth.set_scene(150, small_scene(20.0));
  truth.set_scene(0, small_scene(10.0));  // a late Welcome re-announcing the old scene changes nothing
  CHECK(truth.scenes() == 2);
  CHECK(truth.at(100, 32)->height == before.height);
  CHECK(truth.at(200, 32)->height != old_after.height);
}

TEST_CASE("frame check: within the bound passes, beyond it is bad") {
  GroundTruth truth(30);
  truth.set_scene(0, small_scene());
  const ocean::sim::Frame& t = *truth.at(30, 32);
  const ErrorBounds bounds{0.005, 1.0 / 512};
  std::vector<float> h = t.height, sx = t.slope_x, sz = t.slope_z;
  for (float& v : h) v += 0.0049f;
  FrameError e = frame_error(h, sx, sz, t.height, t.slope_x, t.slope_z);
  CHECK(e.height_m == Approx(0.0049).margin(1e-6));
  CHECK(within_bounds(e, bounds));

  h[17] += 0.002f;  // one sample 6.9 mm off with a 5 mm bound
  e = frame_error(h, sx, sz, t.height, t.slope_x, t.slope_z);
  CHECK_FALSE(within_bounds(e, bounds));

  h = t.height;
  sz[3] += 0.01f;  // a slope off by more than slope_step / 2
  CHECK_FALSE(within_bounds(frame_error(h, sx, sz, t.height, t.slope_x, t.slope_z), bounds));

  std::vector<float> short_frame(10, 0.0f);  // wrong size: never within bounds
  CHECK_FALSE(within_bounds(frame_error(short_frame, {}, {}, t.height, t.slope_x, t.slope_z), bounds));
  std::vector<float> nan_frame = t.height;
  nan_frame[5] = std::numeric_limits<float>::quiet_NaN();
  CHECK_FALSE(within_bounds(frame_error(nan_frame, {}, {}, t.height, t.slope_x, t.slope_z), bounds));
}

TEST_CASE("on time: arrival by offset + tick * period + interpolation delay") {
  const double period = 1.0 / 30, offset = 100.0, delay = 0.1;
  const double render_time = offset + 60 * period + delay;
  CHECK(arrived_on_time(render_time - 0.001, 60, offset, period, delay));
  CHECK(arrived_on_time(render_time, 60, offset, period, delay));
  CHECK_FALSE(arrived_on_time(render_time + 0.001, 60, offset, period, delay));
}

TEST_CASE("client tally: late, bad, stalls, and expected vs received") {
  ClientTally tally(1.0 / 30, 1);
  CHECK(tally.record(10, {true, true}, 0.001));
  CHECK(tally.record(11, {true, false}, 0.001));  // late
  CHECK(tally.record(12, {false, true}, 0.02));   // bad
  CHECK(tally.record(13, {true, true}, 0.001));   // on-time run resumes after a gap: a stall
  CHECK_FALSE(tally.record(13, {true, true}, 0.0));  // the same tick again is not counted
  CHECK(tally.record(16, {true, true}, 0.0));     // 14, 15 missing: another stall
  CHECK(tally.received() == 5);
  CHECK(tally.ok() == 3);
  CHECK(tally.late() == 1);
  CHECK(tally.bad() == 1);
  CHECK(tally.stalls() == 2);
  CHECK(tally.max_error_m() == Approx(0.02));
  CHECK(tally.expected(0, 16) == 7);  // ticks 10..16, counted from the first frame

  // A late copy of an older frame counts once, on time or not; older than the first, not at all.
  CHECK(tally.record(15, {true, true}, 0.0));
  CHECK_FALSE(tally.record(15, {true, true}, 0.0));
  CHECK(tally.record(14, {true, false}, 0.0));
  CHECK_FALSE(tally.record(9, {true, true}, 0.0));
  CHECK(tally.received() == 7);
  CHECK(tally.ok() == 4);
  CHECK(tally.late() == 2);
  CHECK(tally.stalls() == 2);  // only a newer frame after a gap is a stall
  CHECK(tally.record(16 + ClientTally::kWindowTicks + 1, {true, true}, 0.0));
  CHECK_FALSE(tally.record(16, {true, true}, 0.0));  // out of the window: forgotten, not recounted

  // Ticks far apart, and ticks one ring length apart, never stand for each other.
  const ocean::Tick base = 16 + ClientTally::kWindowTicks + 1;
  CHECK(tally.record(base + 128, {true, true}, 0.0));
  CHECK(tally.record(base + 127, {true, true}, 0.0));
  CHECK_FALSE(tally.record(base + 127, {true, true}, 0.0));
  CHECK(tally.record(base + 1000, {true, true}, 0.0));
  CHECK(tally.record(base + 1000 - 128 + 64, {true, true}, 0.0));
  CHECK(tally.record(base + 1001, {true, true}, 0.0));
  CHECK_FALSE(tally.record(base + 1000, {true, true}, 0.0));

  ClientTally every_other(1.0 / 30, 2);
  CHECK(every_other.expected(7, 15) == 4);  // 8, 10, 12, 14 from the Welcome when no frame came
  CHECK(every_other.expected(20, 15) == 0);
}

TEST_CASE("stream facts: the tick of a time, full 64 bits past 2^32 as the wire carries it") {
  ocean::protocol::Welcome w;
  w.tick_period_s = 1.0 / 240;
  w.epoch_unix_ms = 0;
  w.stream.rate_hz = 30;
  const StreamFacts f = StreamFacts::from(w);
  CHECK(f.tick_rate_hz == 240);
  CHECK(f.interval_ticks == 8);
  CHECK(f.tick_at_unix(10.0) == 2400u);
  const double eleven_years_s = 4018.0 * 86400.0;
  const auto true_tick = static_cast<std::uint64_t>(eleven_years_s * 240);
  CHECK(true_tick > 0xFFFFFFFFull);
  CHECK(f.tick_at_unix(eleven_years_s + 1e-4) == true_tick);
  CHECK(f.tick_at_unix(-5.0) == 0u);
}
