// The ground-truth checker and the on-time classification on real sim frames.
#include <catch2/catch.hpp>

#include <limits>
#include <vector>

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

ocean::protocol::SceneParams choppy_scene() {
  ocean::protocol::SceneParams s = small_scene();
  s.choppiness = 1.2;
  return s;
}

// desktop-choppy's bounds, as StreamFacts takes them from its Welcome.
ErrorBounds choppy_bounds() {
  ocean::protocol::Welcome w;
  w.tick_period_s = 1.0 / 30;
  w.stream.rate_hz = 30;
  w.stream.height_step_m = 0.01f;
  w.stream.slope_step = 1.0f / 256;
  w.stream.disp_step_m = 0.01f;
  w.stream.normals = w.stream.choppy = true;
  return StreamFacts::from(w).bounds;
}

void add(std::vector<float>& field, float offset) {
  for (float& v : field) v += offset;
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

TEST_CASE("ground truth: a choppy stream's truth carries displacement and its derivatives") {
  GroundTruth plain(30), choppy(30, true);
  plain.set_scene(0, choppy_scene());
  choppy.set_scene(0, choppy_scene());
  CHECK(plain.at(30, 32)->disp_x.empty());
  const ocean::sim::Frame& t = *choppy.at(30, 32);
  const std::size_t n = 32u * 32u;
  CHECK(t.disp_x.size() == n);
  CHECK(t.disp_z.size() == n);
  CHECK(t.disp_xx.size() == n);
  CHECK(t.disp_zz.size() == n);
  CHECK(t.disp_xz.size() == n);
  CHECK(t.height == plain.at(30, 32)->height);  // the same sea, more channels
}

TEST_CASE("stream facts: a choppy stream bounds displacement by disp_step / 2, derivatives by slope_step / 2") {
  const ErrorBounds b = choppy_bounds();
  CHECK(b.height_m == Approx(0.005));
  CHECK(b.slope == Approx(1.0 / 512));
  CHECK(b.disp_m == Approx(0.005));
  CHECK(b.disp_deriv == Approx(1.0 / 512));
  ocean::protocol::Welcome plain;
  plain.tick_period_s = 1.0 / 30;
  plain.stream.height_step_m = 0.01f;
  plain.stream.normals = true;
  plain.stream.slope_step = 1.0f / 256;
  plain.stream.disp_step_m = 0.01f;  // carried by every Welcome, checked only when choppy
  const StreamFacts f = StreamFacts::from(plain);
  CHECK_FALSE(f.choppy);
  CHECK(f.bounds.disp_m == 0.0);
  CHECK(f.bounds.disp_deriv == 0.0);
}

TEST_CASE("frame check: every choppy channel is held to its own bound") {
  GroundTruth truth(30, true);
  truth.set_scene(0, choppy_scene());
  const ocean::sim::Frame& t = *truth.at(30, 32);
  const ErrorBounds bounds = choppy_bounds();
  REQUIRE(channels_of(t)[ocean::ChannelId::disp_xz].size() == 32u * 32u);
  CHECK(within_bounds(frame_error(channels_of(t), channels_of(t)), bounds));

  // Within the bounds on every channel: passes, and each error is reported on its own.
  ocean::sim::Frame f = t;
  add(f.height, 0.0049f);
  add(f.disp_x, 0.0049f);
  add(f.disp_z, -0.0049f);
  add(f.disp_zz, 0.0019f);
  FrameError e = frame_error(channels_of(f), channels_of(t));
  CHECK(e.height_m == Approx(0.0049).margin(1e-6));
  CHECK(e.disp_m == Approx(0.0049).margin(1e-6));
  CHECK(e.disp_deriv == Approx(0.0019).margin(1e-6));
  CHECK(e.slope == 0.0);
  CHECK(within_bounds(e, bounds));

  // One sample of one channel beyond its bound, every other channel exact: bad. A derivative off
  // by 0.003 is within the displacement bound (0.005) but not its own (slope_step / 2 = 0.00195).
  auto bad_with = [&](std::vector<float> ocean::sim::Frame::*channel, float offset) {
    ocean::sim::Frame g = t;
    (g.*channel)[17] += offset;
    return !within_bounds(frame_error(channels_of(g), channels_of(t)), bounds);
  };
  CHECK(bad_with(&ocean::sim::Frame::disp_x, 0.006f));
  CHECK(bad_with(&ocean::sim::Frame::disp_z, -0.006f));
  CHECK(bad_with(&ocean::sim::Frame::disp_xx, 0.003f));
  CHECK(bad_with(&ocean::sim::Frame::disp_zz, -0.003f));
  CHECK(bad_with(&ocean::sim::Frame::disp_xz, 0.003f));
  CHECK(bad_with(&ocean::sim::Frame::disp_xz, std::numeric_limits<float>::quiet_NaN()));
  CHECK_FALSE(bad_with(&ocean::sim::Frame::disp_xz, 0.0019f));

  // The Jacobian is derived by the decoder, not streamed: not compared.
  ocean::sim::Frame j = t;
  add(j.jacobian, 1.0f);
  CHECK(within_bounds(frame_error(channels_of(j), channels_of(t)), bounds));

  // A choppy stream's frame without its displacement is wrong, not unchecked.
  ocean::sim::Frame missing = t;
  missing.disp_x.clear();
  missing.disp_z.clear();
  CHECK_FALSE(within_bounds(frame_error(channels_of(missing), channels_of(t)), bounds));
  missing = t;
  missing.disp_xz.clear();
  CHECK_FALSE(within_bounds(frame_error(channels_of(missing), channels_of(t)), bounds));
}

TEST_CASE("frame check: a stream without choppy channels is not held to them") {
  GroundTruth truth(30);
  truth.set_scene(0, small_scene());
  const ocean::sim::Frame& t = *truth.at(30, 32);
  const ErrorBounds bounds{0.005, 1.0 / 512};  // disp bounds 0: not streamed
  const FrameError e = frame_error(channels_of(t), channels_of(t));
  CHECK(e.disp_m == 0.0);
  CHECK(e.disp_deriv == 0.0);
  CHECK(within_bounds(e, bounds));
  // Whatever a frame carries beyond its stream's channels is not judged.
  ocean::sim::Frame extra = t;
  extra.disp_x.assign(t.height.size(), 9.0f);
  CHECK(within_bounds(frame_error(channels_of(extra), channels_of(t)), bounds));
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
