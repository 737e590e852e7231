// FrameTimeline: a jittery 30 Hz stream rendered at 60 fps. Every frame's samples equal its tick,
// so a blended sample must equal the render position: continuity is checked on the picture itself.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <random>
#include <set>
#include <thread>

#include "frame_timeline.hpp"
#include "shared_timeline.hpp"

using namespace ocean;
using namespace ocean::client;

namespace {

constexpr double kPeriod = 1.0 / 30.0;

struct Arrival {
  std::uint32_t tick;
  double at;
};

// Frames 1..last sent at tick / 30 s, arriving 50 ms later plus up to 30 ms of jitter.
std::vector<Arrival> schedule(std::uint32_t last, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 0.03);
  std::vector<Arrival> out;
  for (std::uint32_t t = 1; t <= last; ++t) out.push_back({t, t * kPeriod + 0.05 + jitter(rng)});
  std::sort(out.begin(), out.end(), [](const Arrival& a, const Arrival& b) { return a.at < b.at; });
  return out;
}

codec::ReconstructedFrame frame_of(std::uint32_t tick) {
  codec::ReconstructedFrame f;
  f.tick = tick;
  f.complete = true;
  f.height.assign(16, static_cast<float>(tick));
  f.slope_x.assign(16, 0.5f * static_cast<float>(tick));
  f.slope_z.assign(16, 0.0f);
  return f;
}

struct Rendered {
  std::vector<TimelineSample::Status> status;
  std::vector<double> position;  // render_tick
  std::vector<double> shown;     // blended height
};

// Renders at 60 fps from `from` to `to` seconds, pushing each arrival when its time comes.
Rendered render(FrameTimeline& timeline, const std::vector<Arrival>& arrivals, double from, double to) {
  Rendered r;
  std::size_t next = 0;
  std::vector<float> h, sx, sz;
  for (double now = from; now < to; now += 1.0 / 60.0) {
    while (next < arrivals.size() && arrivals[next].at <= now) {
      timeline.push(frame_of(arrivals[next].tick), arrivals[next].tick, arrivals[next].at);
      ++next;
    }
    const TimelineSample s = timeline.sample(now);
    if (s.status == TimelineSample::Status::empty) continue;
    FrameTimeline::blend(s, h, sx, sz);
    r.status.push_back(s.status);
    r.position.push_back(s.render_tick);
    r.shown.push_back(h[0]);
    if (s.status == TimelineSample::Status::interpolating) {
      CHECK(s.weight >= 0.0f);
      CHECK(s.weight < 1.0f);
      CHECK(std::fabs(h[0] - s.render_tick) < 1e-3);  // the picture is where the clock is
      CHECK(std::fabs(sx[0] - 0.5 * s.render_tick) < 1e-3);
    }
  }
  return r;
}

std::size_t first_interpolating(const Rendered& r) {
  for (std::size_t i = 0; i < r.status.size(); ++i)
    if (r.status[i] == TimelineSample::Status::interpolating) return i;
  return r.status.size();
}

}  // namespace

TEST_CASE("timeline: a jittery 30 Hz stream at 60 fps gives monotone, continuous positions", "[timeline]") {
  FrameTimeline timeline;
  CHECK(timeline.interpolation_delay_s() == Approx(3 * kPeriod));
  const Rendered r = render(timeline, schedule(300, 5), 0.0, 9.5);
  REQUIRE(r.position.size() > 500);
  const std::size_t start = first_interpolating(r);
  CHECK(start < 12);  // the first frames arrive, then 3 intervals of delay
  for (std::size_t i = 1; i < r.position.size(); ++i) {
    const double step = r.position[i] - r.position[i - 1];
    CHECK(step > 0.0);
    CHECK(step < 0.5 * 1.03);  // half a tick per render frame, 2% slew at most
    CHECK(std::fabs(r.shown[i] - r.shown[i - 1]) < 0.52);
    if (i > start) CHECK(r.status[i] == TimelineSample::Status::interpolating);
  }
  CHECK(timeline.counters().stalls == 0);
  CHECK(timeline.counters().frames_late == 0);
  REQUIRE(timeline.clock().offset_s());
  CHECK(*timeline.clock().offset_s() >= 0.05);
  CHECK(*timeline.clock().offset_s() < 0.056);  // the least-delayed arrival, not the mean
  CHECK(timeline.frames_held() <= 16);
}

TEST_CASE("timeline: a dropped frame neither freezes nor jumps the picture", "[timeline]") {
  FrameTimeline timeline;
  auto arrivals = schedule(200, 6);
  std::erase_if(arrivals, [](const Arrival& a) { return a.tick == 100 || a.tick == 150 || a.tick == 151; });
  const Rendered r = render(timeline, arrivals, 0.0, 6.5);
  for (std::size_t i = first_interpolating(r) + 1; i < r.position.size(); ++i) {
    CHECK(r.status[i] == TimelineSample::Status::interpolating);
    CHECK(r.shown[i] > r.shown[i - 1]);                 // never frozen
    CHECK(r.shown[i] - r.shown[i - 1] < 0.52);          // never a jump
  }
  CHECK(timeline.counters().stalls == 0);
}

TEST_CASE("timeline: starvation holds the last frame, counts one stall, and resumes", "[timeline]") {
  FrameTimeline timeline;
  auto arrivals = schedule(200, 7);
  std::erase_if(arrivals, [](const Arrival& a) { return a.tick > 100 && a.tick < 130; });  // a 1 s outage
  const Rendered r = render(timeline, arrivals, 0.0, 6.5);
  std::size_t holding = 0;
  for (std::size_t i = 0; i < r.position.size(); ++i)
    if (r.status[i] == TimelineSample::Status::holding) {
      ++holding;
      CHECK(r.shown[i] == 100.0);  // the last frame, held
    }
  CHECK(holding > 20);
  CHECK(timeline.counters().stalls == 1);
  CHECK(timeline.counters().stalled_s > 0.5);
  CHECK(r.status.back() == TimelineSample::Status::interpolating);
  for (std::size_t i = 1; i < r.position.size(); ++i) CHECK(r.position[i] > r.position[i - 1]);  // the clock ran on
}

TEST_CASE("timeline: a frame arriving after its render time is counted late", "[timeline]") {
  FrameTimeline timeline;
  auto arrivals = schedule(120, 8);
  for (Arrival& a : arrivals)
    if (a.tick == 60) a.at += 0.4;
  std::sort(arrivals.begin(), arrivals.end(), [](const Arrival& a, const Arrival& b) { return a.at < b.at; });
  render(timeline, arrivals, 0.0, 4.0);
  CHECK(timeline.counters().frames_late == 1);
  CHECK(timeline.counters().stalls == 0);
}

TEST_CASE("timeline: on a stream, frames held behind a retransmission come in time; without it they are late",
          "[timeline]") {
  // A stream with a 150 ms round trip (as its Pings measure it, queueing included) losing a
  // segment every 3 s: the lost frame and the ones sent after it until the resend arrive
  // together, 1.25 round trips and one send interval after the lost one was sent (RACK).
  constexpr double kRtt = 0.15;
  auto arrivals = schedule(300, 9);
  for (std::uint32_t lost = 45; lost < 300; lost += 90) {
    const double resent = lost * kPeriod + 0.05 + 1.25 * kRtt + kPeriod;
    for (Arrival& a : arrivals)
      if (a.tick >= lost && a.at < resent) a.at = resent;
  }
  std::stable_sort(arrivals.begin(), arrivals.end(), [](const Arrival& a, const Arrival& b) { return a.at < b.at; });
  FrameTimeline datagrams;
  render(datagrams, arrivals, 0.0, 10.2);
  CHECK(datagrams.counters().frames_late >= 6);  // the jitter window learns a stall only by stalling on it
  FrameTimeline stream;
  stream.set_stream_rtt_s(kRtt);
  CHECK(stream.adaptive_delay_s() == Approx(1.25 * kRtt + 2 * kPeriod));  // no jitter seen yet
  const Rendered r = render(stream, arrivals, 0.0, 10.2);  // the last frame, 300, is not passed
  CHECK(stream.counters().frames_late == 0);
  CHECK(stream.counters().stalls == 0);
  for (std::size_t i = first_interpolating(r) + 1; i < r.position.size(); ++i)
    CHECK(r.status[i] == TimelineSample::Status::interpolating);
  CHECK(stream.adaptive_delay_s() >= 1.25 * kRtt + 2 * kPeriod);  // the stalls' jitter may ask more
  CHECK(FrameTimeline::retransmission_lateness_s(0.0, kPeriod) == 0.0);  // no stream, no cover
}

TEST_CASE("timeline: frame buffers are reused in steady state", "[timeline]") {
  FrameTimelineConfig config;
  config.capacity = 8;
  FrameTimeline timeline(config);
  const auto arrivals = schedule(400, 9);
  std::set<const float*> buffers;
  std::size_t next = 0;
  for (double now = 0.0; now < 13.0; now += 1.0 / 60.0) {
    while (next < arrivals.size() && arrivals[next].at <= now) {
      timeline.push(frame_of(arrivals[next].tick), arrivals[next].tick, arrivals[next].at);
      ++next;
    }
    const TimelineSample s = timeline.sample(now);
    if (now > 1.0 && s.a) {
      buffers.insert(s.a->height.data());
      buffers.insert(s.b->height.data());
    }
  }
  CHECK(buffers.size() <= config.capacity);
}

TEST_CASE("timeline: with an extrapolator a starved timeline keeps moving instead of holding", "[timeline]") {
  FrameTimeline timeline;
  int asked = 0;
  timeline.set_extrapolator([&](std::uint32_t tick, codec::ReconstructedFrame& out) {
    ++asked;
    out = frame_of(tick);  // a perfect predictor of this linear "sea"
    return true;
  });
  auto arrivals = schedule(200, 7);
  std::erase_if(arrivals, [](const Arrival& a) { return a.tick > 100 && a.tick < 130; });
  const Rendered r = render(timeline, arrivals, 0.0, 6.5);
  std::size_t extrapolating = 0;
  for (std::size_t i = first_interpolating(r) + 1; i < r.position.size(); ++i) {
    CHECK(r.status[i] != TimelineSample::Status::holding);
    extrapolating += r.status[i] == TimelineSample::Status::extrapolating;
    CHECK(r.shown[i] > r.shown[i - 1]);
    CHECK(r.shown[i] - r.shown[i - 1] < 0.52);
    CHECK(std::fabs(r.shown[i] - r.position[i]) < 1e-3);
  }
  CHECK(extrapolating > 20);
  CHECK(timeline.counters().stalls == 1);
  CHECK(timeline.counters().frames_extrapolated >= 25);
  CHECK(timeline.counters().frames_extrapolated == static_cast<std::uint64_t>(asked));
}

TEST_CASE("timeline: SharedTimeline hands frames from a network thread to a render thread", "[timeline]") {
  SharedTimeline shared;
  const auto arrivals = schedule(120, 10);
  std::atomic<bool> done{false};
  std::thread network([&] {
    for (const Arrival& a : arrivals) shared.push(frame_of(a.tick), a.tick, a.at);
    done = true;
  });
  std::vector<float> h, sx, sz;
  while (!done) shared.render(0.0, h, sx, sz);  // concurrent use; the time does not matter here
  network.join();
  // Frames 105..120 are held (capacity 16); render where the newest arrived, 3 intervals behind.
  const RenderedFrame r = shared.render(arrivals.back().at, h, sx, sz);
  CHECK(r.status == TimelineSample::Status::interpolating);
  REQUIRE(h.size() == 16);
  CHECK(std::fabs(h[0] - r.render_tick) < 1e-3);
  CHECK(r.tick_b > r.tick_a);
  CHECK(shared.counters().frames_pushed == 120);
}
