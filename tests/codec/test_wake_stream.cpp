// The wake lattice (codec version 6): the sim's wake of vessels on circuits, streamed beside a
// band of the sea at a lag of 3 ticks, decodes bit for bit as the encoder reconstructs it and
// within half a step of the truth in every channel; once the hulls are lifted their free waves
// cost next to nothing (the damped recurrence predicts them), so the bytes go to the corrections
// near the hulls. (Lag 1, keys and a change of scene: the mobile_wake vector.)
#include "cascade_frame.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "ocean.hpp"
#include "vessel_track.hpp"
#include "wake_field.hpp"
#include "wake_frame.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;
namespace sim = ocean::sim;

namespace wake_test {

constexpr double kRegion = 512.0;

StreamConfig wake_stream(bool choppy) {
  StreamConfig c;
  c.grid = 64;
  c.rate_hz = 30;
  c.normals = true;
  c.choppy = choppy;
  c.wake = {64, kRegion, -256.0, -256.0, 0.05, 1e-6};
  return c;
}

// n vessels on square circuits round the region's middle at 5..9 m/s.
std::vector<sim::VesselTrack> fleet(int n) {
  std::vector<sim::VesselTrack> out;
  for (int v = 0; v < n; ++v) {
    const double half = 60.0 + 15.0 * v, speed = 5.0 + 4.0 * v / std::max(1, n - 1);
    const double c = kRegion / 2, leg = 2 * half / speed;
    sim::VesselTrack t;
    t.id = static_cast<std::uint32_t>(v + 1);
    t.hull = {24.0, 6.0, 1.5};
    t.repeat = true;
    t.points = {{0, c - half, c - half}, {leg, c + half, c - half}, {2 * leg, c + half, c + half},
                {3 * leg, c - half, c + half}, {4 * leg, c - half, c - half}};
    out.push_back(t);
  }
  return out;
}

struct Truth {
  sim::Ocean ocean;
  sim::WakeField wake;
  sim::WakeSampler sampler;
  std::vector<sim::VesselTrack> tracks;
  double choppiness;

  Truth(const model::SceneParams& scene, const StreamConfig& c, std::vector<sim::VesselTrack> vessels)
      : ocean(scene), wake(sim::WakeRegion{kRegion, 128, 9.81, scene.depth_m, c.wake.decay_per_s, c.wake.viscosity_m2ps}),
        tracks(std::move(vessels)), choppiness(scene.choppiness) {}

  // Steps the wake to `tick` (one tick at a time, hulls at mid-step) and returns the stream's frame.
  // After `lift_tick` the hulls are gone and the wake rings down freely.
  std::uint64_t lift_tick = ~std::uint64_t{0};

  sim::Frame at(std::uint64_t tick, const StreamConfig& c) {
    const double dt = c.dt_s();
    while (wake.time_s() < static_cast<double>(tick) * dt - 1e-9) {
      const double mid = wake.time_s() + 0.5 * dt;
      std::vector<sim::HullPose> poses;
      if (tick <= lift_tick)
        for (const auto& t : tracks) poses.push_back(sim::pose_at(t, mid));
      wake.step(dt, poses);
    }
    sim::Frame f, w;
    ocean.evaluate_band(static_cast<double>(tick) * dt, c.grid, c.grid, f, {true, c.choppy});
    sampler.sample(wake, c.wake.grid, {true, c.choppy}, choppiness, w);
    sim::append_cascade_frame(f, w);  // the wake lattice's samples follow the sea's, as a cascade's would
    return f;
  }
};

TruthView wake_view(const sim::Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz};
}

double wake_worst(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(static_cast<double>(a[i]) - b[i]));
  return m;
}

model::SceneParams calm() {
  model::SceneParams s;
  s.size_x = s.size_z = 64;
  s.wind_speed_mps = 6.0;
  s.choppiness = 0.8;
  return s;
}

}  // namespace wake_test
using namespace wake_test;

TEST_CASE("eight vessels' wakes stream within half a step, bit for bit, at a lag of three ticks", "[wake]") {
  for (const bool choppy : {false, true}) {
    const StreamConfig config = wake_stream(choppy);
    REQUIRE(validate(config).empty());
    const model::SceneParams scene = calm();
    Truth truth(scene, config, fleet(8));
    Encoder encoder(config);
    Decoder decoder(config);
    encoder.set_scene(0, 1, scene);
    decoder.add_scene(0, 1, scene);
    const std::uint64_t last = 900;  // 30 s: 20 s of vessels, then 10 s of their wakes alone
    truth.lift_tick = 600;
    std::map<std::uint64_t, StateId> ids;
    double err_h = 0, err_s = 0, err_d = 0, err_dd = 0;
    bool bitwise = true;
    std::size_t forced_bytes = 0, forced_frames = 0, free_bytes = 0, free_frames = 0;
    double wake_peak = 0.0;
    for (std::uint64_t tick = 0; tick <= last; ++tick) {
      const sim::Frame f = truth.at(tick, config);
      encoder.add_truth(tick, wake_view(f));
      const auto encoded = tick == 0 ? encoder.encode_key(tick) : encoder.encode_delta(tick, ids.at(tick < 3 ? 0 : tick - 3));
      ids[tick] = encoded->id;
      for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
      const ReconstructedFrame* shown = decoder.latest();
      REQUIRE(shown);
      REQUIRE(shown->tick == tick);
      bitwise = bitwise && shown->height == encoded->reconstruction.height && shown->slope_x == encoded->reconstruction.slope_x;
      err_h = std::max(err_h, wake_worst(shown->height, f.height));
      err_s = std::max({err_s, wake_worst(shown->slope_x, f.slope_x), wake_worst(shown->slope_z, f.slope_z)});
      if (choppy) err_d = std::max({err_d, wake_worst(shown->disp_x, f.disp_x), wake_worst(shown->disp_z, f.disp_z)});
      if (choppy) err_dd = std::max({err_dd, wake_worst(shown->disp_xx, f.disp_xx), wake_worst(shown->disp_xz, f.disp_xz)});
      if (tick > 300 && tick <= 600) {
        forced_bytes += encoded->stats.payload_bytes;
        ++forced_frames;
      }
      if (tick > 700) {
        free_bytes += encoded->stats.payload_bytes;
        ++free_frames;
      }
      for (std::size_t i = 64 * 64; i < f.height.size(); ++i) wake_peak = std::max(wake_peak, std::fabs(static_cast<double>(f.height[i])));
    }
    const double forced = static_cast<double>(forced_bytes) / forced_frames, free = static_cast<double>(free_bytes) / free_frames;
    std::printf("wake stream (%s, 8 vessels, 64 x 64 wake over %g m): %.1f payload bytes per frame while they sail "
                "(10-20 s), %.1f once their wakes ring down alone (23-30 s); wake peak %.3f m; errors h %.2g s %.2g d %.2g\n",
                choppy ? "choppy" : "plain", kRegion, forced, free, wake_peak, err_h, err_s, err_d);
    // The damped recurrence predicts the free waves: once no hull forces them they cost next to
    // nothing, while the hulls' forcing costs corrections every frame.
    CHECK(free < 0.1 * forced);
    CHECK(bitwise);
    CHECK(wake_peak > 0.1);
    CHECK(err_h <= 0.5 * config.height_step_m);
    CHECK(err_s <= 0.5 * config.slope_step);
    if (choppy) CHECK(err_d <= 0.5 * config.disp_step_m);
    if (choppy) CHECK(err_dd <= 0.5 * config.slope_step);
  }
}
