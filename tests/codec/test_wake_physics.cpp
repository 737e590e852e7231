// The wake's physics from what a client decodes (issue 34): a vessel's wake streamed through the
// codec - the server's sim::EpochWake as the truth, an encoder and a client's decoder that know
// the track - and measured on the decoder's own output, not the sim's arrays: the transverse
// wavelength along the track is 2 pi U^2 / g within 2 % at 5, 7 and 9 m/s, at most 15 % of the
// energy lies beyond 27 degrees of the track, and once the vessel is gone the decoded wake fades
// as the damping says.
#include "cascade_frame.hpp"
#include "decoder.hpp"
#include "dominant_wavenumber.hpp"
#include "encoder.hpp"
#include "epoch_wake.hpp"
#include "ocean.hpp"
#include "wake_frame.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;
namespace sim = ocean::sim;

namespace wake_physics {

using std::numbers::pi;
constexpr double kG = 9.81;
constexpr int kRate = 15;       // server ticks a second
constexpr int kFrameTicks = 15;  // a frame a second, each a delta from the one before
constexpr int kN = 256;          // 4 m samples over 1024 m

StreamConfig stream() {
  StreamConfig c;
  c.grid = 16;  // the sea: a token lattice of a near calm
  c.rate_hz = kRate;
  c.normals = false;
  c.wake = {kN, 1024.0, 0.0, 0.0, 0.02, 1e-6, 60 * kRate};
  return c;
}

model::SceneParams near_calm() {
  model::SceneParams s;
  s.size_x = s.size_z = 16;
  s.wind_speed_mps = 1.0;
  return s;
}

// Along +x at U from x = 50 m on z = 512 m, for `sail_s` seconds, then moored there.
model::VesselTrack straight(double speed, double sail_s) {
  model::VesselTrack v;
  v.id = 1;
  v.hull = {20.0, 8.0, 1.5};
  v.points = {{0.0, 50.0, 512.0}, {sail_s, 50.0 + speed * sail_s, 512.0}};
  return v;
}

// The decoded wake lattice (the samples after the sea's) at each second up to `seconds`.
struct Streamed {
  std::vector<std::vector<float>> frames;  // one per second
};
Streamed stream_wake(const model::VesselTrack& vessel, int seconds) {
  const StreamConfig c = stream();
  const model::SceneParams scene = near_calm();
  sim::Ocean sea(scene);
  sim::EpochWake truth(sim::WakeRegion{1024.0, kN, kG, scene.depth_m, c.wake.decay_per_s, c.wake.viscosity_m2ps}, 0.0, 0.0,
                       {vessel}, kRate, c.wake.epoch_ticks);
  sim::WakeSampler sampler;
  Encoder encoder(c);
  Decoder decoder(c);
  encoder.set_scene(0, 1, scene);
  decoder.add_scene(0, 1, scene);
  encoder.set_vessels({vessel});
  decoder.set_vessels({vessel});
  Streamed out;
  StateId previous{};
  for (int s = 0; s <= seconds; ++s) {
    const std::uint64_t tick = static_cast<std::uint64_t>(s) * kFrameTicks;
    truth.advance_to(static_cast<std::int64_t>(tick));
    sim::Frame f, w;
    sea.evaluate_band(static_cast<double>(tick) / kRate, c.grid, c.grid, f, {false, false});
    sampler.sample(truth.fields(), kN, {false, false}, 0.0, w);
    sim::append_cascade_frame(f, w);
    encoder.add_truth(tick, TruthView{f.height, {}, {}, {}, {}, {}, {}, {}});
    const auto encoded = s == 0 ? encoder.encode_key(tick) : encoder.encode_delta(tick, previous);
    previous = encoded->id;
    for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
    const ReconstructedFrame* shown = decoder.latest();
    REQUIRE(shown);
    REQUIRE(shown->complete);
    out.frames.emplace_back(shown->height.begin() + 16 * 16, shown->height.end());
  }
  return out;
}


}  // namespace wake_physics
using namespace wake_physics;
using ocean::test_support::dominant_wavenumber;

TEST_CASE("from decoded frames: the transverse wavelength along the track is 2 pi U^2 / g", "[wake]") {
  for (double speed : {5.0, 7.0, 9.0}) {
    const Streamed s = stream_wake(straight(speed, 1000.0), 80);
    const std::vector<float>& h = s.frames.back();
    const double x_end = 50.0 + speed * 80.0, wavelength = 2.0 * pi * speed * speed / kG;
    std::vector<double> track;
    for (double back = 2.0 * wavelength; back < 6.0 * wavelength; back += 4.0)
      track.push_back(h[128 * kN + static_cast<int>(std::lround((x_end - back) / 4.0))]);
    const double k0 = kG / (speed * speed);
    const double k = dominant_wavenumber(track, 4.0, 0.6 * k0, 1.4 * k0);
    std::printf("decoded wake at %.0f m/s: transverse wavelength %.2f m, 2 pi U^2 / g = %.2f m\n", speed, 2.0 * pi / k,
                wavelength);
    CHECK(k == Approx(k0).epsilon(0.02));
    if (speed != 7.0) continue;
    double inside = 0.0, outside = 0.0;
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const double x = 4.0 * i, z = 4.0 * j;
        const double back = x_end - x, side = std::fabs(z - 512.0), r = std::hypot(back, side);
        if (back <= 0.0 || r < 80.0 || r > 300.0 || x < 300.0) continue;  // near field and the start's rings out
        const double e = static_cast<double>(h[static_cast<std::size_t>(j) * kN + i]) * h[static_cast<std::size_t>(j) * kN + i];
        (std::atan2(side, back) * 180.0 / pi > 27.0 ? outside : inside) += e;
      }
    REQUIRE(inside > 0.0);
    std::printf("decoded wake energy beyond 27 degrees of the track: %.1f %%\n", 100.0 * outside / (inside + outside));
    CHECK(outside / (inside + outside) < 0.15);
  }
}

TEST_CASE("from decoded frames: once the vessel stops, its wake fades as the damping says", "[wake]") {
  // Sails 40 s, then lies still: its moored hollow stays, the waves it made ring down. Their
  // energy, away from the hull, over a wave period, between 50 and 60 s.
  const Streamed s = stream_wake(straight(7.0, 40.0), 62);
  const auto energy = [&](int from_s) {
    double e = 0.0;
    for (int t = from_s; t < from_s + 2; ++t)
      for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
          const double x = 4.0 * i - (50.0 + 7.0 * 40.0), z = 4.0 * j - 512.0;
          if (std::hypot(x, z) < 60.0) continue;  // the moored hull's hollow
          const double v = s.frames[static_cast<std::size_t>(t)][static_cast<std::size_t>(j) * kN + i];
          e += v * v;
        }
    return e;
  };
  const double e50 = energy(50), e60 = energy(60);
  const double expected = std::exp(-2.0 * 0.02 * 10.0);
  std::printf("decoded wake energy 60 s / 50 s after the start: %.3f (the damping says %.3f)\n", e60 / e50, expected);
  CHECK(e60 / e50 == Approx(expected).epsilon(0.1));
}
