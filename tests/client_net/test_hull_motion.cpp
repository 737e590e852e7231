// HullMotion: a hull on a known sea - a long swell along its track, written on one lattice here -
// heaves with the swell under it, pitches bow-up on the swell's front, holds still when the sea is
// flat, eases (never snaps) between frames, leaves out its own wake depression, and is absent
// outside its presence.
#include "frame_channels.hpp"
#include "hull_motion.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace ocean;
using ocean::client::FrameChannels;
using ocean::client::HullMotion;
using std::numbers::pi;

namespace {

// The sea's lattice (256 m, 64 samples) and a 64 m wake square at (-32, -32) with 32 samples.
codec::StreamConfig config() {
  codec::StreamConfig c;
  c.grid = 64;
  c.patch_x_m = c.patch_z_m = 256.0;
  c.wake = {32, 64.0, -32.0, -32.0, 0.05, 1e-6, 1800};
  return c;
}

// A swell a cos(k x - w t) along x on the sea's lattice; the wake lattice holds a bowl `bowl` deep
// under (0, 0) (a hull's own pressure depression).
FrameChannels sea(const codec::StreamConfig& c, double a, double t, double bowl) {
  FrameChannels f;
  const double k = 2.0 * pi * 2.0 / 256.0, w = std::sqrt(9.81 * k);  // a 128 m swell, 9 s
  const std::size_t total = c.samples();
  for (auto* v : {&f.height, &f.slope_x, &f.slope_z}) v->assign(total, 0.0f);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const double x = i * 4.0;
      f.height[static_cast<std::size_t>(j * 64 + i)] = static_cast<float>(a * std::cos(k * x - w * t));
      f.slope_x[static_cast<std::size_t>(j * 64 + i)] = static_cast<float>(-a * k * std::sin(k * x - w * t));
    }
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const double x = -32.0 + i * 2.0, z = -32.0 + j * 2.0;
      f.height[64 * 64 + static_cast<std::size_t>(j * 32 + i)] = static_cast<float>(-bowl * std::exp(-(x * x + z * z) / 60.0));
    }
  return f;
}

model::VesselTrack moored() {
  model::VesselTrack v;
  v.id = 4;
  v.hull = {24.0, 6.0, 1.5};
  v.points = {{0.0, 0.0, 0.0}};
  return v;
}

}  // namespace

TEST_CASE("a hull heaves and pitches with the swell under it, not with its own depression") {
  const codec::StreamConfig c = config();
  const codec::SurfaceQuery query(c);
  const std::vector<model::VesselTrack> fleet{moored()};
  HullMotion motion;
  double worst = 0.0, pitch_seen = 0.0;
  for (int frame = 0; frame < 600; ++frame) {  // 20 s at 30 frames a second
    const double t = frame / 30.0;
    const FrameChannels f = sea(c, 1.5, t, 1.4);
    const auto& hulls = motion.update(fleet, query, codec::surface_fields(f), t);
    REQUIRE(hulls.size() == 1);
    const client::HullState& h = hulls.front();
    CHECK(h.speed_mps == Approx(0.0).margin(1e-9));
    worst = std::max(worst, std::abs(h.heave_m - h.surface_m[4]));
    pitch_seen = std::max(pitch_seen, std::abs(h.pitch_rad));
    // Its bottom never stands higher above the water (depression included) than its draft.
    CHECK(h.keel_above_m < h.hull.draft_m);
  }
  // Within 10 % of the swell's height (3 m): the lag of its easing and the hull's averaging.
  CHECK(worst < 0.1 * 3.0);
  CHECK(pitch_seen > 0.02);  // a 128 m swell of 1.5 m pitches a 24 m hull by a few degrees
}

TEST_CASE("a hull eases towards a sudden change, and takes a jump in time at once") {
  const codec::StreamConfig c = config();
  const codec::SurfaceQuery query(c);
  const std::vector<model::VesselTrack> fleet{moored()};
  HullMotion motion;
  const FrameChannels flat = sea(c, 0.0, 0.0, 0.0), risen = sea(c, 0.0, 0.0, -1.0);  // a 1 m hump
  motion.update(fleet, query, codec::surface_fields(flat), 10.0);
  const double after_one = motion.update(fleet, query, codec::surface_fields(risen), 10.0 + 1.0 / 30.0).front().heave_m;
  CHECK(after_one == Approx(0.0).margin(1e-12));  // the wake lattice's hump is not the sea's
  const FrameChannels swell = sea(c, 1.0, 0.0, 0.0);
  const double eased = motion.update(fleet, query, codec::surface_fields(swell), 10.0 + 2.0 / 30.0).front().heave_m;
  const double target = motion.update(fleet, query, codec::surface_fields(swell), 50.0).front().heave_m;  // a jump
  CHECK(target > 0.5);
  CHECK(eased > 0.0);
  CHECK(eased < 0.5 * target);  // one frame of a 0.15 s easing moves a fifth of the way
}

TEST_CASE("a hull is posed only while present, at its track's place, heading and speed") {
  const codec::StreamConfig c = config();
  const codec::SurfaceQuery query(c);
  model::VesselTrack v = moored();
  v.points = {{0.0, -20.0, 0.0}, {10.0, 0.0, 20.0}};  // 2.83 m/s towards +x +z
  v.presence = {5.0, 20.0, 0.0};
  const std::vector<model::VesselTrack> fleet{v};
  const FrameChannels flat = sea(c, 0.0, 0.0, 0.0);
  HullMotion motion;
  CHECK(motion.update(fleet, query, codec::surface_fields(flat), 4.0).empty());
  const auto& hulls = motion.update(fleet, query, codec::surface_fields(flat), 7.5);
  REQUIRE(hulls.size() == 1);
  CHECK(hulls[0].x_m == Approx(-5.0));
  CHECK(hulls[0].z_m == Approx(15.0));
  CHECK(hulls[0].dir_x == Approx(std::sqrt(0.5)));
  CHECK(hulls[0].speed_mps == Approx(std::sqrt(8.0)).epsilon(1e-6));
  CHECK(motion.update(fleet, query, codec::surface_fields(flat), 25.5).empty());
}

TEST_CASE("a dropped object (a round hull) makes rings but is no vessel to pose") {
  const codec::StreamConfig c = config();
  const codec::SurfaceQuery query(c);
  model::VesselTrack object = moored();
  object.id = 60;
  object.hull = {4.0, 4.0, 2.0};  // what ocean-server makes of a drop of 4 m
  const std::vector<model::VesselTrack> fleet{moored(), object};
  const FrameChannels flat = sea(c, 0.0, 0.0, 0.0);
  HullMotion motion;
  const auto& hulls = motion.update(fleet, query, codec::surface_fields(flat), 1.0);
  REQUIRE(hulls.size() == 1);
  CHECK(hulls[0].id == 4);
  CHECK(client::is_dropped_object(object.hull));
  CHECK_FALSE(client::is_dropped_object(moored().hull));
}
