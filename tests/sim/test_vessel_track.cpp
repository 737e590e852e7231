// Vessel tracks: poses between waypoints, circuits, stops, and the tracks refused with a reason.
#include "vessel_track.hpp"
#include "wake_field.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <span>

using namespace ocean::sim;
using namespace ocean::model;

namespace {

using std::numbers::pi;

// The heading a pose points along, in radians from +x towards +z.
double heading(const HullPose& p) { return std::atan2(p.dir_z, p.dir_x); }

VesselTrack l_shaped() {
  VesselTrack t;
  t.id = 7;
  t.points = {{0.0, 100.0, 100.0}, {10.0, 200.0, 100.0}, {20.0, 200.0, 200.0}};
  return t;
}

VesselTrack square_circuit() {
  VesselTrack t;
  t.id = 3;
  t.repeat = true;
  t.points = {{0, 100, 100}, {10, 200, 100}, {20, 200, 200}, {30, 100, 200}, {40, 100, 100}};
  return t;
}

}  // namespace

TEST_CASE("a vessel sails straight between waypoints, heading along its leg") {
  const VesselTrack t = l_shaped();
  HullPose p = pose_at(t, 5.0);
  CHECK(p.x_m == Approx(150.0));
  CHECK(p.z_m == Approx(100.0));
  CHECK(heading(p) == Approx(0.0).margin(1e-12));
  p = pose_at(t, 15.0);
  CHECK(p.x_m == Approx(200.0));
  CHECK(p.z_m == Approx(150.0));
  CHECK(heading(p) == Approx(pi / 2));
  // Before the start at its first waypoint, after the end moored at its last, heading kept.
  p = pose_at(t, -3.0);
  CHECK(p.x_m == 100.0);
  CHECK(heading(p) == Approx(0.0).margin(1e-12));
  p = pose_at(t, 1e6);
  CHECK(p.x_m == Approx(200.0));
  CHECK(p.z_m == Approx(200.0));
  CHECK(heading(p) == Approx(pi / 2));
}

TEST_CASE("a circuit repeats with the period of its last waypoint, without a jump at the wrap") {
  const VesselTrack t = square_circuit();
  REQUIRE(validate(t, TrackLimits{}).empty());
  for (double s : {3.0, 17.5, 29.0, 39.9}) {
    const HullPose a = pose_at(t, s), b = pose_at(t, s + 40.0 * 25);
    CHECK(b.x_m == Approx(a.x_m));
    CHECK(b.z_m == Approx(a.z_m));
    CHECK(heading(b) == Approx(heading(a)));
  }
  const HullPose before = pose_at(t, 40.0 - 1e-6), after = pose_at(t, 40.0 + 1e-6);
  CHECK(std::hypot(after.x_m - before.x_m, after.z_m - before.z_m) < 1e-3);
}

TEST_CASE("a vessel that stops keeps its heading") {
  VesselTrack t;
  t.points = {{0, 100, 100}, {10, 100, 200}, {20, 100, 200}};
  CHECK(heading(pose_at(t, 15.0)) == Approx(pi / 2));
  CHECK(pose_at(t, 15.0).z_m == Approx(200.0));
}

TEST_CASE("tracks no vessel could sail are refused, naming the vessel, the waypoint and the limit") {
  const TrackLimits limits;
  auto refused = [&](VesselTrack t, const std::string& words) {
    const std::string error = validate(t, limits);
    CAPTURE(error);
    CHECK(error.find(words) != std::string::npos);
    CHECK(error.find("vessel " + std::to_string(t.id)) == 0);
  };
  VesselTrack fast = l_shaped();
  fast.points[1].t_s = 4.0;  // 100 m in 4 s
  refused(fast, "needs 25 m/s; vessels sail at most 20 m/s");
  VesselTrack outside = l_shaped();
  outside.points[2].z_m = 2000.0;
  refused(outside, "waypoint 2: (200, 2000) m is outside the world");
  VesselTrack backwards = l_shaped();
  backwards.points[2].t_s = 5.0;
  refused(backwards, "waypoint 2: t_s = 5 is invalid");
  VesselTrack late = l_shaped();
  late.points[0].t_s = 1.0;
  refused(late, "0 for the first waypoint");
  VesselTrack open = square_circuit();
  open.points.pop_back();
  refused(open, "a repeating track is a circuit");
  VesselTrack empty = l_shaped();
  empty.points.clear();
  refused(empty, "at least one waypoint");
  VesselTrack wide = l_shaped();
  wide.hull.beam_m = 50.0;
  refused(wide, "beam_m = 50 is invalid");
  VesselTrack deep = l_shaped();
  deep.hull.draft_m = 40.0;
  refused(deep, "draft_m = 40 is invalid");
  CHECK(validate(l_shaped(), limits).empty());
}

TEST_CASE("a vessel on a circuit leaves a wake that follows it round") {
  WakeRegion region;
  region.size_m = 1024.0;
  region.n = 256;
  WakeField field(region);
  VesselTrack t;
  t.hull = Hull{20.0, 8.0, 1.5};
  t.repeat = true;
  t.points = {{0, 300, 300}, {50, 700, 300}, {100, 700, 700}, {150, 300, 700}, {200, 300, 300}};  // 8 m/s
  REQUIRE(validate(t, TrackLimits{}).empty());
  for (int s = 0; s < 600; ++s) {
    const HullPose mid = pose_at(t, (s + 0.5) * 0.1);
    field.step(0.1, std::span<const HullPose>(&mid, 1));
  }
  // At t = 60 s the vessel is 80 m up the second leg: behind it (down the first leg) the sea
  // moves, ahead of it (the third leg, not yet sailed) only the long forerunners of its waves
  // have arrived.
  const double behind = std::fabs(field.height_at(600.0, 300.0)) + std::fabs(field.height_at(640.0, 300.0)) +
                        std::fabs(field.height_at(620.0, 300.0));
  const double ahead = std::fabs(field.height_at(500.0, 700.0)) + std::fabs(field.height_at(400.0, 700.0));
  CAPTURE(behind, ahead);
  CHECK(behind > 0.01);
  CHECK(ahead < 0.05 * behind);
}

TEST_CASE("a vessel waiting at its first waypoint already faces its first leg; a circuit keeps its arrival heading") {
  VesselTrack t;
  t.points = {{0, 100, 100}, {10, 100, 100}, {20, 100, 200}};  // waits 10 s, then sails +z
  CHECK(heading(pose_at(t, 5.0)) == Approx(pi / 2));
  CHECK(heading(pose_at(t, -1.0)) == Approx(pi / 2));
  VesselTrack circuit;
  circuit.repeat = true;  // waits at the start of each lap, having arrived heading -z
  circuit.points = {{0, 100, 100}, {5, 100, 100}, {15, 200, 100}, {25, 200, 200}, {35, 100, 200}, {45, 100, 100}};
  REQUIRE(validate(circuit, TrackLimits{}).empty());
  CHECK(heading(pose_at(circuit, 45.0 + 2.0)) == Approx(heading(pose_at(circuit, 44.9))));
}

TEST_CASE("a hull presses only while present: always, for a while, or again and again") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(present_at(Presence{}, -1e9));
  CHECK(present_at(Presence{}, 1e9));
  // Added at 10 s, removed at 25 s.
  const Presence once{10.0, 15.0, 0.0};
  CHECK_FALSE(present_at(once, 9.999));
  CHECK(present_at(once, 10.0));
  CHECK(present_at(once, 24.999));
  CHECK_FALSE(present_at(once, 25.0));
  CHECK(present_at(Presence{10.0, inf, 0.0}, 1e9));
  CHECK_FALSE(present_at(Presence{10.0, inf, 0.0}, 9.0));
  // A splash of 1 s every 20 s from 5 s, also before its start (a server runs years from its epoch).
  const Presence splashes{5.0, 1.0, 20.0};
  CHECK(present_at(splashes, 5.5));
  CHECK_FALSE(present_at(splashes, 6.5));
  CHECK(present_at(splashes, 25.2));
  CHECK(present_at(splashes, -14.5));  // u = -19.5, taken modulo 20: 0.5
  CHECK_FALSE(present_at(splashes, -15.5));
  CHECK(present_at(splashes, 5.0 + 20.0 * 1e7 + 0.25));
}

TEST_CASE("presences no command could mean are refused, naming the field") {
  const TrackLimits limits;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  auto refused = [&](Presence p, const std::string& words) {
    VesselTrack t = l_shaped();
    t.presence = p;
    const std::string error = validate(t, limits);
    CAPTURE(error);
    CHECK(error.find(words) != std::string::npos);
    CHECK(error.find("vessel 7") == 0);
  };
  refused({nan, inf, 0.0}, "present_from_s");
  refused({inf, inf, 0.0}, "present_from_s");
  refused({2e12, 1.0, 0.0}, "present_from_s");
  refused({0.0, 0.0, 0.0}, "present_for_s");
  refused({0.0, -1.0, 0.0}, "present_for_s");
  refused({0.0, nan, 0.0}, "present_for_s");
  refused({0.0, 1.0, -1.0}, "present_every_s");
  refused({0.0, 1.0, inf}, "present_every_s");
  refused({-inf, 5.0, 0.0}, "needs a start");
  refused({-inf, 5.0, 10.0}, "needs a start");
  refused({0.0, 2.0, 1.0}, "lasts at most that long");
  for (const Presence& ok : {Presence{}, Presence{3.0, 1.0, 0.0}, Presence{-1e12, 1e12, 1e12}, Presence{0.0, inf, 0.0}}) {
    VesselTrack t = l_shaped();
    t.presence = ok;
    CHECK(validate(t, limits).empty());
  }
}
