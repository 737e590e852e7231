// VesselTrack: where a vessel is at any time - waypoints with the times it passes them, straight
// at constant speed between them, heading along the leg it is on - and the check that refuses a
// track no vessel could sail (too fast, out of the world, times out of order). Pure: time is an
// argument, so every replica computes the same poses from the same track, and only + - * / and
// sqrt (no libm), so the sim and every decoder compute the same bits (the codec's wake forcing,
// CODEC.md 7.9, uses these poses).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ocean::model {

// A hull as the water feels it: a Gaussian pressure patch of the hull's displacement, standard
// deviations a quarter of the length and beam, peak pressure rho g draft (hull_pressure.hpp).
struct Hull {
  double length_m = 40.0;
  double beam_m = 8.0;
  double draft_m = 2.0;
  bool operator==(const Hull&) const = default;
};

// Where a hull is at one instant (x east, z north, metres) and which way it points: the unit
// vector (dir_x, dir_z) of its heading.
struct HullPose {
  Hull hull;
  double x_m = 0.0;
  double z_m = 0.0;
  double dir_x = 1.0, dir_z = 0.0;
};

struct Waypoint {
  double t_s = 0.0;  // seconds from the track's start
  double x_m = 0.0;
  double z_m = 0.0;
  bool operator==(const Waypoint&) const = default;
};

// When a hull presses on the water. A vessel: always (the default). A dropped object: for a moment,
// its splash - from `from_s` for `for_s` seconds, and with `every_s` > 0 again every `every_s`
// seconds (a buoy's mooring line jerking, a scenario's repeated drop). A live command (add,
// remove, a new course) is a track present from its effective tick, or until it.
struct Presence {
  double from_s = -std::numeric_limits<double>::infinity();
  double for_s = std::numeric_limits<double>::infinity();  // > 0
  double every_s = 0.0;  // 0: once; > 0: from_s finite and for_s <= every_s
  bool operator==(const Presence&) const = default;
};

// Whether a hull with this presence presses at t seconds: with u = t - from_s (taken modulo
// every_s into [0, every_s) when it repeats), present when 0 <= u < for_s. Only - and fmod: exact
// in every arithmetic.
bool present_at(const Presence& presence, double t_s);

struct VesselTrack {
  std::uint32_t id = 0;
  Hull hull;
  // At least one; times strictly increasing from 0. A repeating track is a circuit: its last
  // waypoint is its first again, and it sails round with the period of the last time.
  std::vector<Waypoint> points;
  bool repeat = false;
  Presence presence;
  bool operator==(const VesselTrack&) const = default;
};

struct TrackLimits {
  double max_speed_mps = 20.0;
  double world_min_m = 0.0, world_max_m = 1024.0;  // every waypoint inside, on both axes
  double max_hull_length_m = 400.0, max_draft_m = 25.0;
};

// Empty when usable, else what is wrong, naming the vessel, the waypoint or leg and the limit.
std::string validate(const VesselTrack& track, const TrackLimits& limits);

// The pose at t seconds from the track's start: before it, at the first waypoint; after the end of
// a track that does not repeat, at the last (moored: the heading of its last leg).
HullPose pose_at(const VesselTrack& track, double t_s);

}  // namespace ocean::model
