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
Streamed stream_wake(const std::vector<model::VesselTrack>& vessels, int seconds) {
  const StreamConfig c = stream();
  const model::SceneParams scene = near_calm();
  sim::Ocean sea(scene);
  sim::EpochWake truth(sim::WakeRegion{1024.0, kN, kG, scene.depth_m, c.wake.decay_per_s, c.wake.viscosity_m2ps}, 0.0, 0.0,
                       vessels, kRate, c.wake.epoch_ticks);
  sim::WakeSampler sampler;
  Encoder encoder(c);
  Decoder decoder(c);
  encoder.set_scene(0, 1, scene);
  decoder.add_scene(0, 1, scene);
  encoder.set_vessels(vessels);
  decoder.set_vessels(vessels);
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
Streamed stream_wake(const model::VesselTrack& vessel, int seconds) {
  return stream_wake(std::vector<model::VesselTrack>{vessel}, seconds);
}

// Energy in rings round (cx, cz): the sum of h^2 over the cells whose distance lies in each 2 m
// bin, then a running mean over `width_m` (a wavelength: h^2 oscillates within one).
std::vector<double> ring_energy(const std::vector<float>& h, double cx, double cz, double width_m) {
  std::vector<double> bins(256, 0.0);
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double r = std::hypot(4.0 * i - cx, 4.0 * j - cz);
      const auto b = static_cast<std::size_t>(r / 2.0);
      if (b < bins.size()) bins[b] += static_cast<double>(h[static_cast<std::size_t>(j) * kN + i]) * h[static_cast<std::size_t>(j) * kN + i];
    }
  const int half = std::max(1, static_cast<int>(width_m / 4.0));
  std::vector<double> smooth(bins.size(), 0.0);
  for (int b = 0; b < static_cast<int>(bins.size()); ++b)
    for (int d = -half; d <= half; ++d)
      if (b + d >= 0 && b + d < static_cast<int>(bins.size())) smooth[static_cast<std::size_t>(b)] += bins[static_cast<std::size_t>(b + d)];
  return smooth;
}

// The ring's radius (the most energetic, beyond the near field) and the wavenumber of its waves
// (the heights along the four axes out of the centre, averaged, read around that radius).
struct Ring {
  double radius_m, k;
};
Ring ring_of(const std::vector<float>& h, double cx, double cz, double k_guess) {
  double k = k_guess;
  double radius = 0.0;
  for (int pass = 0; pass < 3; ++pass) {  // the wavelength sets the smoothing, the radius the window
    const std::vector<double> e = ring_energy(h, cx, cz, 2.0 * pi / k);
    std::size_t best = 20;  // from 40 m out
    for (std::size_t b = 20; b < e.size(); ++b)
      if (e[b] > e[best]) best = b;
    // Between bins: the vertex of the parabola through the peak and its neighbours.
    const double left = e[best - 1], mid = e[best], right = best + 1 < e.size() ? e[best + 1] : mid;
    const double curve = left - 2.0 * mid + right;
    const double offset = curve < 0.0 ? 0.5 * (left - right) / curve : 0.0;
    radius = 2.0 * (static_cast<double>(best) + offset) + 1.0;
    const double lambda = 2.0 * pi / k;
    std::vector<double> profile;
    for (double r = std::max(8.0, radius - 1.5 * lambda); r <= radius + 1.5 * lambda; r += 4.0) {
      const int d = static_cast<int>(std::lround(r / 4.0)), ci = static_cast<int>(cx / 4.0), cj = static_cast<int>(cz / 4.0);
      const auto at = [&](int i, int j) { return static_cast<double>(h[static_cast<std::size_t>(j) * kN + i]); };
      profile.push_back(0.25 * (at(ci + d, cj) + at(ci - d, cj) + at(ci, cj + d) + at(ci, cj - d)));
    }
    k = ocean::test_support::dominant_wavenumber(profile, 4.0, 0.5 * k_guess, 2.0 * k_guess);
  }
  return {radius, k};
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

TEST_CASE("from decoded frames: a dropped object's ring advances at the group velocity of its waves", "[wake]") {
  // An object 8 m across pressing 1 m deep for 2 s from t = 5 s, in the middle of the region
  // (a [[drop]]: a round hull present for its splash). Its rings, read every 6 s from 30 to 54 s
  // after the splash: the speed of the most energetic ring (a least-squares slope of its radius)
  // against the deep-water group velocity 0.5 sqrt(g / k) of the waves found there.
  model::VesselTrack drop;
  drop.id = 9;
  drop.hull = {8.0, 8.0, 1.0};
  drop.points = {{0.0, 512.0, 512.0}};
  drop.presence = {5.0, 2.0, 0.0};
  const Streamed s = stream_wake(drop, 60);
  const auto peak = [](const std::vector<float>& h) {
    double m = 0.0;
    for (float v : h) m = std::max(m, static_cast<double>(std::fabs(v)));
    return m;
  };
  CHECK(peak(s.frames[4]) < 1e-5);  // nothing before the splash
  REQUIRE(peak(s.frames[40]) > 1e-3);
  // The splash lasts about a half period of the waves it excites most: w = pi / 2 s, k = w^2 / g.
  const double k_guess = (pi / 2.0) * (pi / 2.0) / kG;
  std::vector<Ring> rings;
  std::vector<double> times;
  for (int t = 36; t <= 60; t += 6) {
    rings.push_back(ring_of(s.frames[static_cast<std::size_t>(t)], 512.0, 512.0, k_guess));
    times.push_back(t);
  }
  double mean_t = 0.0, mean_r = 0.0, mean_k = 0.0;
  for (std::size_t i = 0; i < rings.size(); ++i) mean_t += times[i], mean_r += rings[i].radius_m, mean_k += rings[i].k;
  mean_t /= rings.size(), mean_r /= rings.size(), mean_k /= rings.size();
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    num += (times[i] - mean_t) * (rings[i].radius_m - mean_r);
    den += (times[i] - mean_t) * (times[i] - mean_t);
  }
  const double speed = num / den, group = 0.5 * std::sqrt(kG / mean_k);
  std::string described;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    char item[64];
    std::snprintf(item, sizeof item, " %.0f s: %.0f m (%.1f m waves);", times[i] - 6.0, rings[i].radius_m, 2.0 * pi / rings[i].k);
    described += item;
  }
  std::printf("decoded rings after the splash:%s advancing at %.2f m/s, group velocity %.2f m/s\n", described.c_str(), speed,
              group);
  CHECK(speed == Approx(group).epsilon(0.1));
  const Ring& early = rings.front();
  const Ring& late = rings.back();
  CHECK(early.k == Approx(late.k).epsilon(0.15));  // the ring carries the same waves as it spreads
}
