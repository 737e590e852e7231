// Vessel commands (an admin's add, course, remove, drop) as the fleet every decoder predicts from:
// nothing presses differently before the command's tick, the command's effect from it on, and
// every command no vessel could obey refused with a reason.
#include "vessel_commands.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace ocean;
using namespace ocean::server;
using model::VesselTrack;

namespace {

constexpr int kRate = 30;
const FleetRules kRules{-256.0, -256.0, 512.0, kRate, 1800};
constexpr Tick kToday = 30 * 3600 * 24;  // a day in
constexpr Tick kAt = kToday + 30;

double mid(Tick t) { return (static_cast<double>(t) + 0.5) / kRate; }

std::vector<VesselTrack> harbour() {
  VesselTrack ferry;
  ferry.id = 1;
  ferry.hull = {30.0, 8.0, 2.0};
  ferry.repeat = true;
  ferry.points = {{0, -150, -150}, {60, 150, -150}, {120, 150, 150}, {180, -150, 150}, {240, -150, -150}};
  VesselTrack buoy;
  buoy.id = 9;
  buoy.hull = {2.0, 2.0, 1.0};
  buoy.points = {{0, 20, 20}};
  buoy.presence = {3.0, 1.0, 10.0};
  return {ferry, buoy};
}

// The hulls pressing at a step, as (id, x, z, heading) in fleet order.
std::vector<std::array<double, 4>> pressing(const std::vector<VesselTrack>& fleet, double t_s) {
  std::vector<std::array<double, 4>> out;
  for (const VesselTrack& v : fleet)
    if (model::present_at(v.presence, t_s)) {
      const model::HullPose p = model::pose_at(v, t_s);
      out.push_back({static_cast<double>(v.id), p.x_m, p.z_m, std::atan2(p.dir_z, p.dir_x)});
    }
  return out;
}

// Before `from` the new fleet presses exactly as the old one did.
void same_before(const std::vector<VesselTrack>& before, const std::vector<VesselTrack>& after) {
  for (Tick t = kAt - 3 * 1800; t < kAt; t += 7) REQUIRE(pressing(before, mid(t)) == pressing(after, mid(t)));
  REQUIRE(pressing(before, mid(kAt - 1)) == pressing(after, mid(kAt - 1)));
}

protocol::VesselCommand command(wire::VesselAction action, std::uint32_t id) {
  protocol::VesselCommand c;
  c.action = action;
  c.id = id;
  c.hull = {20.0, 5.0, 1.2};
  c.size_m = 1.0;
  return c;
}

}  // namespace

TEST_CASE("a vessel added, turned and removed changes nothing before the command's tick", "[vessels]") {
  const std::vector<VesselTrack> fleet = harbour();
  protocol::VesselCommand add = command(wire::VesselAction::add, 50);
  add.x_m = 0.0, add.z_m = 0.0, add.heading_deg = 90.0, add.speed_mps = 8.0;
  const FleetChange added = apply_vessel_command(fleet, add, kAt, kToday, kRules);
  REQUIRE(added.error == "");
  same_before(fleet, added.fleet);
  auto now_pressing = pressing(added.fleet, mid(kAt));
  REQUIRE(now_pressing.size() == pressing(fleet, mid(kAt)).size() + 1);
  // Ten seconds on, 80 m along +z from where it was put.
  const model::HullPose sailed = model::pose_at(added.fleet.back(), mid(kAt + 300));
  CHECK(sailed.x_m == Approx(0.0).margin(1e-9));
  CHECK(sailed.z_m == Approx(80.0 + 8.0 * 0.5 / kRate).epsilon(1e-9));
  // At the square's edge it stops: 256 m out, 32 s after it set off.
  CHECK(model::pose_at(added.fleet.back(), mid(kAt) + 100.0).z_m == Approx(256.0));

  protocol::VesselCommand turn = command(wire::VesselAction::course, 50);
  turn.heading_deg = 180.0, turn.speed_mps = 5.0;
  const Tick later = kAt + 300;
  const FleetChange turned = apply_vessel_command(added.fleet, turn, later, kToday + 300, kRules);
  REQUIRE(turned.error == "");
  for (Tick t = later - 400; t < later; t += 3) REQUIRE(pressing(added.fleet, mid(t)) == pressing(turned.fleet, mid(t)));
  // From there it heads -x at 5 m/s, from where it was.
  const auto at = [&](Tick t) {
    for (const auto& p : pressing(turned.fleet, mid(t)))
      if (p[0] == 50.0) return p;
    FAIL("vessel 50 is not pressing");
    return std::array<double, 4>{};
  };
  CHECK(at(later + 30)[1] == Approx(-5.0 * (1.0 + 0.5 / kRate)).epsilon(1e-9));
  CHECK(at(later + 30)[2] == Approx(80.0).epsilon(1e-9));
  CHECK(std::fabs(at(later + 30)[3]) == Approx(std::numbers::pi));

  const FleetChange removed = apply_vessel_command(turned.fleet, command(wire::VesselAction::remove, 1), later + 60,
                                                   kToday + 360, kRules);
  REQUIRE(removed.error == "");
  for (Tick t = later; t < later + 60; ++t) REQUIRE(pressing(turned.fleet, mid(t)) == pressing(removed.fleet, mid(t)));
  for (const auto& p : pressing(removed.fleet, mid(later + 60))) CHECK(p[0] != 1.0);
}

TEST_CASE("a dropped object presses for a second from the command's tick", "[vessels]") {
  protocol::VesselCommand drop = command(wire::VesselAction::drop, 70);
  drop.x_m = 10.0, drop.z_m = -20.0, drop.size_m = 3.0;
  const FleetChange dropped = apply_vessel_command(harbour(), drop, kAt, kToday, kRules);
  REQUIRE(dropped.error == "");
  same_before(harbour(), dropped.fleet);
  const VesselTrack& object = dropped.fleet.back();
  CHECK(object.hull == model::Hull{3.0, 3.0, 1.5});
  CHECK(model::present_at(object.presence, mid(kAt)));
  CHECK(model::present_at(object.presence, mid(kAt + 29)));
  CHECK_FALSE(model::present_at(object.presence, mid(kAt + 30)));
}

TEST_CASE("commands no vessel could obey are refused, naming why", "[vessels]") {
  const auto refused = [](protocol::VesselCommand c, const std::string& words) {
    const FleetChange r = apply_vessel_command(harbour(), c, kAt, kToday, kRules);
    INFO(r.error);
    CHECK(r.error.find(words) != std::string::npos);
    CHECK(r.fleet.empty());
  };
  protocol::VesselCommand add = command(wire::VesselAction::add, 1);
  refused(add, "vessel 1 is already at sea");
  add.id = 2, add.x_m = 400.0;
  refused(add, "outside the world");
  add.x_m = 0.0, add.speed_mps = 21.0;
  refused(add, "speed 21 m/s");
  add.speed_mps = 5.0, add.hull.draft_m = 30.0;
  refused(add, "draft_m = 30 is invalid");
  // The edges themselves are accepted: 20 m/s, a hull at the square's corner, the largest object.
  protocol::VesselCommand fastest = command(wire::VesselAction::add, 3);
  fastest.x_m = -256.0, fastest.z_m = 255.0, fastest.speed_mps = 20.0, fastest.heading_deg = 0.0;
  CHECK(apply_vessel_command(harbour(), fastest, kAt, kToday, kRules).error == "");
  protocol::VesselCommand largest = command(wire::VesselAction::drop, 4);
  largest.x_m = 256.0, largest.z_m = -256.0, largest.size_m = 50.0;
  CHECK(apply_vessel_command(harbour(), largest, kAt, kToday, kRules).error == "");
  refused(command(wire::VesselAction::course, 5), "vessel 5 is not at sea");
  refused(command(wire::VesselAction::remove, 5), "vessel 5 is not at sea");
  protocol::VesselCommand buoy = command(wire::VesselAction::course, 9);
  CHECK(apply_vessel_command(harbour(), buoy, 30 * 3, 0, kRules).error.find("cannot be steered") != std::string::npos);
  protocol::VesselCommand drop = command(wire::VesselAction::drop, 80);
  drop.size_m = 60.0;
  refused(drop, "size 60 m");
  refused(command(wire::VesselAction::none, 3), "add, course, remove or drop");
}

TEST_CASE("the fleet keeps to 32 tracks: old ones are forgotten, then commands are refused", "[vessels]") {
  std::vector<VesselTrack> fleet = harbour();
  Tick now = kToday;
  // Thirty objects dropped a second apart fill the list.
  for (std::uint32_t id = 100; id < 130; ++id, now += 30) {
    protocol::VesselCommand drop = command(wire::VesselAction::drop, id);
    const FleetChange r = apply_vessel_command(fleet, drop, now + 30, now, kRules);
    REQUIRE(r.error == "");
    fleet = r.fleet;
  }
  REQUIRE(fleet.size() == 32);
  protocol::VesselCommand one_more = command(wire::VesselAction::drop, 200);
  CHECK(apply_vessel_command(fleet, one_more, now + 30, now, kRules).error.find("at most 32") != std::string::npos);
  // Three epochs (three minutes) later the splashes are gone from every wake a tick still holds.
  now += 3 * 1800;
  const FleetChange r = apply_vessel_command(fleet, one_more, now + 30, now, kRules);
  REQUIRE(r.error == "");
  CHECK(r.fleet.size() == 3);  // the two from the config and the new splash
}

TEST_CASE("20 m/s is a speed a vessel is given, at any tick of the day", "[vessels]") {
  // The leg's end time rounds near 1e5..1e7 s: it must never come out a hair above 20 m/s.
  int refused = 0;
  std::string why;
  for (int i = 0; i < 500; ++i) {
    protocol::VesselCommand add = command(wire::VesselAction::add, 40);
    add.x_m = -200.0 + 0.77 * i, add.z_m = 13.0 - 0.31 * i, add.heading_deg = 7.3 * i, add.speed_mps = 20.0;
    const Tick from = kToday * (1 + i % 97) + static_cast<Tick>(i) * 7919;
    const FleetChange r = apply_vessel_command(harbour(), add, from, from - 30, kRules);
    refused += !r.error.empty();
    if (!r.error.empty()) why += std::to_string(i) + ": " + r.error + "\n";
    if (r.error.empty()) {
      const VesselTrack& v = r.fleet.back();
      REQUIRE(v.points.size() == 3);
      const double leg = std::hypot(v.points[2].x_m - v.points[1].x_m, v.points[2].z_m - v.points[1].z_m) /
                         (v.points[2].t_s - v.points[1].t_s);
      CHECK(leg <= 20.0);
      CHECK(leg > 20.0 * (1.0 - 1e-9));  // as asked, not slower than rounding needs
    }
  }
  INFO(why);
  CHECK(refused == 0);
}

TEST_CASE("an object's id is its own: it cannot be steered, removed or taken while its splash is due", "[vessels]") {
  protocol::VesselCommand drop = command(wire::VesselAction::drop, 70);
  drop.x_m = 10.0, drop.z_m = -20.0;
  const FleetChange dropped = apply_vessel_command(harbour(), drop, kAt, kToday, kRules);
  REQUIRE(dropped.error == "");
  const auto during = [&](protocol::VesselCommand c) { return apply_vessel_command(dropped.fleet, c, kAt + 10, kToday + 10, kRules); };
  CHECK(during(command(wire::VesselAction::course, 70)).error.find("cannot be steered") != std::string::npos);
  CHECK(during(command(wire::VesselAction::remove, 70)).error.find("ends by itself") != std::string::npos);
  protocol::VesselCommand again = command(wire::VesselAction::add, 70);
  CHECK(during(again).error.find("already at sea or due") != std::string::npos);
  // Once its splash is over, the id is free again.
  CHECK(apply_vessel_command(dropped.fleet, again, kAt + 60, kToday + 60, kRules).error == "");
  // A config's repeating object between two splashes (the buoy, 3 s into every 10): still its id.
  protocol::VesselCommand buoy = command(wire::VesselAction::drop, 9);
  const Tick between = 30 * 6;  // 6 s: after the first splash, before the second
  CHECK(apply_vessel_command(harbour(), buoy, between, between - 30, kRules).error.find("already at sea or due") !=
        std::string::npos);
}
