// The wake's physics from its own heights: the Kelvin wedge, the transverse wavelength along the
// track, and the decay once a vessel is gone - none of it tuned into the model.
#include "dominant_wavenumber.hpp"
#include "epoch_wake.hpp"
#include "wake_field.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <complex>
#include <numbers>
#include <vector>

using namespace ocean::sim;
using ocean::test_support::dominant_wavenumber;

namespace {

using std::numbers::pi;
constexpr double kG = 9.81;

WakeRegion test_region(double depth_m = 1e300) {
  WakeRegion r;
  r.size_m = 1024.0;
  r.n = 256;  // 4 m samples
  r.depth_m = depth_m;
  return r;
}

// A hull that starts at (x0, 512) and runs along +x at U, its pressure eased in over 20 s so
// that the start radiates little; returns the field after `seconds` and the hull's last x.
struct Run {
  WakeField field;
  double x_end;
};
Run run_straight(double speed, double seconds, double x0 = 100.0, double depth_m = 1e300) {
  Run run{WakeField(test_region(depth_m)), x0};
  const double dt = 0.1;
  Hull hull{20.0, 8.0, 1.5};
  for (int step = 0; step * dt < seconds; ++step) {
    const double t_mid = (step + 0.5) * dt;
    const double ease = t_mid < 20.0 ? std::pow(std::sin(0.5 * pi * t_mid / 20.0), 2) : 1.0;
    HullPose pose{Hull{hull.length_m, hull.beam_m, hull.draft_m * ease}, x0 + speed * t_mid, 512.0, 1.0, 0.0};
    run.field.step(dt, std::span<const HullPose>(&pose, 1));
    run.x_end = x0 + speed * (step + 1) * dt;
  }
  return run;
}


}  // namespace

TEST_CASE("a hull at rest sits in its hydrostatic hollow, and the field stays real") {
  // A beam the 4 m samples resolve (a narrower hull's hollow is the band-limited one).
  const HullPose pose{Hull{40.0, 16.0, 2.0}, 512.0, 512.0, std::cos(0.3), std::sin(0.3)};
  // Damped so that the start-up oscillation dies within the minute: what stays is the hollow.
  WakeRegion still = test_region();
  still.decay_per_s = 0.2;
  WakeField damped(still);
  for (int i = 0; i < 600; ++i) damped.step(0.1, std::span<const HullPose>(&pose, 1));
  CHECK(damped.height_at(512.0, 512.0) == Approx(-2.0).epsilon(0.05));  // the draft, minus the region's mean
  CHECK(std::fabs(damped.height_at(700.0, 512.0)) < 0.02);
  const std::vector<double> h = damped.heights();
  CHECK(h[128 * 256 + 128] == Approx(damped.height_at(512.0, 512.0)).margin(1e-9));
}

TEST_CASE("the transverse wavelength along the track is 2 pi U^2 / g") {
  for (double speed : {5.0, 7.0, 9.0}) {
    const Run run = run_straight(speed, 90.0, 50.0);
    const std::vector<double> h = run.field.heights();
    // Behind the hull along its track (row z = 512), from 2 to 6 wavelengths back: clear of the
    // hull's near field and of where it started.
    const double wavelength = 2.0 * pi * speed * speed / kG;
    std::vector<double> track;
    for (double back = 2.0 * wavelength; back < 6.0 * wavelength; back += 4.0) {
      const int i = static_cast<int>(std::lround((run.x_end - back) / 4.0));
      track.push_back(h[128 * 256 + i]);
    }
    const double k0 = kG / (speed * speed);
    const double k = dominant_wavenumber(track, 4.0, 0.6 * k0, 1.4 * k0);
    CAPTURE(speed, wavelength, 2.0 * pi / k);
    CHECK(k == Approx(k0).epsilon(0.02));
  }
}

TEST_CASE("in shallow water the transverse waves are the ones whose phase speed is the hull's") {
  // U^2 = (g / k) tanh(k h): at U = 7 m/s over 10 m of water, k is 3.6 % below deep water's g/U^2.
  const double speed = 7.0, depth = 10.0;
  double k0 = kG / (speed * speed);
  for (int i = 0; i < 50; ++i) k0 = kG * std::tanh(k0 * depth) / (speed * speed);
  const Run run = run_straight(speed, 90.0, 50.0, depth);
  const std::vector<double> h = run.field.heights();
  const double wavelength = 2.0 * pi / k0;
  std::vector<double> track;
  for (double back = 2.0 * wavelength; back < 6.0 * wavelength; back += 4.0)
    track.push_back(h[128 * 256 + static_cast<int>(std::lround((run.x_end - back) / 4.0))]);
  const double k = dominant_wavenumber(track, 4.0, 0.6 * k0, 1.4 * k0);
  CAPTURE(k0, kG / (speed * speed));
  CHECK(k == Approx(k0).epsilon(0.015));
  CHECK(k < 0.985 * kG / (speed * speed));  // told apart from the deep-water answer
}

TEST_CASE("a dropped object's rings: at radius r and time t the waves are those of group velocity r / t") {
  WakeField field(test_region());
  // An object of about a tonne lands at the centre and is gone after half a second.
  const HullPose drop{Hull{8.0, 8.0, 1.0}, 512.0, 512.0, 1.0, 0.0};
  for (int s = 0; s < 5; ++s) field.step(0.1, std::span<const HullPose>(&drop, 1));
  for (int s = 0; s < 400; ++s) field.step(0.1, {});
  const double t = field.time_s() - 0.25;  // from the middle of the impulse
  const std::vector<double> h = field.heights();
  for (double r : {100.0, 140.0, 180.0}) {
    // Deep water: c_g = sqrt(g / k) / 2, so the local wavenumber is g / (4 (r / t)^2).
    const double expected = kG / (4.0 * (r / t) * (r / t));
    std::vector<double> ray;
    for (double x = r - 30.0; x <= r + 30.0; x += 4.0)
      ray.push_back(h[128 * 256 + 128 + static_cast<int>(std::lround(x / 4.0))]);
    const double k = dominant_wavenumber(ray, 4.0, 0.5 * expected, 1.5 * expected);
    CAPTURE(r, t, expected);
    CHECK(k == Approx(expected).epsilon(0.08));
  }
}

TEST_CASE("the wake's energy lies inside the Kelvin wedge") {
  const double speed = 7.0;
  const Run run = run_straight(speed, 90.0);
  const std::vector<double> h = run.field.heights();
  double inside = 0.0, outside = 0.0;
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i) {
      const double x = 4.0 * i, z = 4.0 * j;
      const double back = run.x_end - x, side = std::fabs(z - 512.0);
      const double r = std::hypot(back, side);
      if (back <= 0.0 || r < 80.0 || r > 300.0 || x < 300.0) continue;  // near field and the start's rings out
      const double angle = std::atan2(side, back) * 180.0 / pi;
      (angle > 27.0 ? outside : inside) += h[static_cast<std::size_t>(j) * 256 + i] * h[static_cast<std::size_t>(j) * 256 + i];
    }
  CAPTURE(inside, outside);
  REQUIRE(inside > 0.0);
  std::printf("wake energy beyond 27 degrees of the track: %.1f %%\n", 100.0 * outside / (inside + outside));
  CHECK(outside / (inside + outside) < 0.15);
}

TEST_CASE("once the hull is gone its wake fades as the damping says") {
  Run run = run_straight(7.0, 40.0);
  auto energy = [&] {
    // Sum of squared heights over a wave period is proportional to the wave energy.
    double e = 0.0;
    for (int s = 0; s < 20; ++s) {
      for (double v : run.field.heights()) e += v * v;
      run.field.step(0.1, {});
    }
    return e;
  };
  const double e0 = energy();  // t 40..42
  for (int s = 0; s < 80; ++s) run.field.step(0.1, {});  // to t = 50
  const double e1 = energy();  // t 50..52
  const double gamma = test_region().decay_per_s;  // viscosity adds ~1e-7 at these wavelengths
  CHECK(e1 / e0 == Approx(std::exp(-2.0 * gamma * 10.0)).epsilon(0.03));
}

TEST_CASE("the same poses give the same wake bit for bit") {
  const Run a = run_straight(6.0, 5.0), b = run_straight(6.0, 5.0);
  CHECK(a.field.heights() == b.field.heights());
}

TEST_CASE("any damping gives finite heights: an overdamped sea relaxes, it never overflows") {
  for (double decay : {0.02, 3.0, 800.0, 1e6}) {
    WakeRegion r = test_region();
    r.decay_per_s = decay;
    WakeField field(r);
    const HullPose pose{Hull{40.0, 16.0, 2.0}, 512.0, 512.0, 1.0, 0.0};
    for (int s = 0; s < 20; ++s) field.step(1.0, std::span<const HullPose>(&pose, 1));
    CAPTURE(decay);
    for (double v : field.heights()) REQUIRE(std::isfinite(v));
    CHECK(std::fabs(field.height_at(512.0, 512.0)) <= 2.5);
  }
}

// The server's wake is a function of the tracks alone (EpochWake): a replica that starts late, or
// a ground truth asked for an older tick, computes the same bits as one that stepped all along.
TEST_CASE("the wake at a tick is the same however it was reached") {
  ocean::model::VesselTrack v;
  v.hull = Hull{20.0, 5.0, 1.2};
  v.repeat = true;
  v.points = {{0, -100, -100}, {25, 100, -100}, {50, 100, 100}, {75, -100, 100}, {100, -100, -100}};  // 8 m/s
  WakeRegion region;
  region.size_m = 512.0;
  region.n = 64;
  region.decay_per_s = 0.3;  // e^{-3} of an amplitude in one 10 s epoch
  const auto make = [&] { return EpochWake(region, -256.0, -256.0, {v}, 10, 100); };
  EpochWake all_along = make(), late = make(), back = make();
  for (std::int64_t t = 0; t <= 450; ++t) all_along.advance_to(t);
  late.advance_to(450);
  back.advance_to(600);
  back.advance_to(450);
  const auto same = [](const EpochWake& a, const EpochWake& b) {
    const auto fa = a.fields(), fb = b.fields();
    if (fa.size() != fb.size()) return false;
    for (std::size_t i = 0; i < fa.size(); ++i)
      if (fa[i]->modes() != fb[i]->modes()) return false;
    return true;
  };
  CHECK(all_along.fields().size() == 2);  // epochs 3 and 4 of 100 ticks
  CHECK(same(all_along, late));
  CHECK(same(all_along, back));
  // And the dropped history was small: the wake of epochs 3 and 4 against one stepped from 0.
  WakeField from_rest(region);
  for (std::int64_t t = 0; t < 450; ++t) {
    HullPose pose = ocean::model::pose_at(v, (static_cast<double>(t) + 0.5) / 10);
    pose.x_m += 256.0;
    pose.z_m += 256.0;
    from_rest.step(0.1, std::span<const HullPose>(&pose, 1));
  }
  double diff = 0, size = 0;
  for (std::size_t m = 0; m < from_rest.modes().size(); ++m) {
    std::complex<double> sum{};
    for (const WakeField* f : all_along.fields()) sum += f->modes()[m];
    diff += std::norm(sum - from_rest.modes()[m]);
    size += std::norm(from_rest.modes()[m]);
  }
  CAPTURE(diff, size);
  // Dropped: forcing before tick 300, at least 15 s old, its amplitude below e^{-4.5}.
  CHECK(diff < 1e-3 * size);
}
