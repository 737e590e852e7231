#include "vessel_track.hpp"

#include "param_message.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocean::model {
namespace {

std::string vessel(const VesselTrack& track) { return "vessel " + std::to_string(track.id) + ": "; }

// Presence times and lengths: within ~31,700 years, so t - from_s keeps sub-millisecond precision.
constexpr double kMaxPresenceS = 1e12;

bool inside(double v, const TrackLimits& limits) { return v >= limits.world_min_m && v <= limits.world_max_m; }

// The heading of the leg from a to b as a unit vector; a leg of no length keeps `previous`.
struct Direction {
  double x = 1.0, z = 0.0;
};
Direction heading_of(const Waypoint& a, const Waypoint& b, Direction previous) {
  const double dx = b.x_m - a.x_m, dz = b.z_m - a.z_m;
  if (dx == 0.0 && dz == 0.0) return previous;
  const double length = std::sqrt(dx * dx + dz * dz);
  return {dx / length, dz / length};
}

}  // namespace

std::string validate(const VesselTrack& track, const TrackLimits& limits) {
  const Hull& h = track.hull;
  if (!(h.length_m > 0.0 && h.length_m <= limits.max_hull_length_m))
    return vessel(track) + bad_param("length_m", h.length_m, "(0, " + format_value(limits.max_hull_length_m) + "] m");
  if (!(h.beam_m > 0.0 && h.beam_m <= h.length_m))
    return vessel(track) + bad_param("beam_m", h.beam_m, "(0, length] m");
  if (!(h.draft_m > 0.0 && h.draft_m <= limits.max_draft_m))
    return vessel(track) + bad_param("draft_m", h.draft_m, "(0, " + format_value(limits.max_draft_m) + "] m");
  if (track.points.empty()) return vessel(track) + "a track needs at least one waypoint";
  for (std::size_t i = 0; i < track.points.size(); ++i) {
    const Waypoint& p = track.points[i];
    const std::string where = vessel(track) + "waypoint " + std::to_string(i) + ": ";
    if (!inside(p.x_m, limits) || !inside(p.z_m, limits))
      return where + "(" + format_value(p.x_m) + ", " + format_value(p.z_m) + ") m is outside the world [" +
             format_value(limits.world_min_m) + ", " + format_value(limits.world_max_m) + "] m";
    if (i == 0 && p.t_s != 0.0) return where + bad_param("t_s", p.t_s, "0 for the first waypoint");
    if (i == 0) continue;
    const Waypoint& q = track.points[i - 1];
    if (!(p.t_s > q.t_s) || !std::isfinite(p.t_s))
      return where + bad_param("t_s", p.t_s, "a finite time after the previous waypoint's " + format_value(q.t_s) + " s");
    const double speed = std::hypot(p.x_m - q.x_m, p.z_m - q.z_m) / (p.t_s - q.t_s);
    if (speed > limits.max_speed_mps)
      return where + "the leg from waypoint " + std::to_string(i - 1) + " needs " + format_value(speed) +
             " m/s; vessels sail at most " + format_value(limits.max_speed_mps) + " m/s";
  }
  const Waypoint &first = track.points.front(), &last = track.points.back();
  if (track.repeat && (track.points.size() < 2 || last.x_m != first.x_m || last.z_m != first.z_m))
    return vessel(track) + "a repeating track is a circuit: its last waypoint must be its first again";
  const Presence& p = track.presence;
  const bool from_ok = p.from_s == -std::numeric_limits<double>::infinity() ||
                       (std::isfinite(p.from_s) && std::fabs(p.from_s) <= kMaxPresenceS);
  if (!from_ok)
    return vessel(track) + bad_param("present_from_s", p.from_s, "-inf or a time within 1e12 s");
  if (!(p.for_s > 0.0) || (std::isfinite(p.for_s) && p.for_s > kMaxPresenceS))
    return vessel(track) + bad_param("present_for_s", p.for_s, "(0, 1e12] s or inf");
  if (!(p.every_s >= 0.0 && p.every_s <= kMaxPresenceS))
    return vessel(track) + bad_param("present_every_s", p.every_s, "0 (once) or (0, 1e12] s");
  if (std::isfinite(p.for_s) && !std::isfinite(p.from_s))
    return vessel(track) + "a presence of " + format_value(p.for_s) + " s needs a start (present_from_s)";
  if (p.every_s > 0.0 && !(std::isfinite(p.from_s) && p.for_s <= p.every_s))
    return vessel(track) + "a presence that repeats every " + format_value(p.every_s) +
           " s needs a finite start and lasts at most that long (present_for_s " + format_value(p.for_s) + " s)";
  return {};
}

bool present_at(const Presence& presence, double t_s) {
  if (presence.every_s > 0.0) {
    double u = std::fmod(t_s - presence.from_s, presence.every_s);
    if (u < 0.0) u += presence.every_s;
    return u < presence.for_s;
  }
  if (!(t_s >= presence.from_s)) return false;
  return presence.for_s == std::numeric_limits<double>::infinity() || t_s - presence.from_s < presence.for_s;
}

HullPose pose_at(const VesselTrack& track, double t_s) {
  const std::vector<Waypoint>& p = track.points;
  HullPose pose{track.hull, p.front().x_m, p.front().z_m, 1.0, 0.0};
  if (p.size() == 1) return pose;
  // Before the first leg that moves (a dwell at the start), the heading it will sail; on a circuit,
  // the one it arrived with, so a lap joins the next without a turn.
  Direction heading;
  if (track.repeat)
    for (std::size_t i = 1; i < p.size(); ++i) heading = heading_of(p[i - 1], p[i], heading);
  else
    for (std::size_t i = p.size() - 1; i > 0; --i) heading = heading_of(p[i - 1], p[i], heading);
  const double period = p.back().t_s;
  double t = t_s;
  if (track.repeat && t > period) t = std::fmod(t, period);
  if (t <= 0.0) {
    pose.dir_x = heading.x;
    pose.dir_z = heading.z;
    return pose;
  }
  for (std::size_t i = 1; i < p.size(); ++i) {
    heading = heading_of(p[i - 1], p[i], heading);
    if (t <= p[i].t_s || i + 1 == p.size()) {
      const double f = std::min(1.0, (t - p[i - 1].t_s) / (p[i].t_s - p[i - 1].t_s));
      pose.x_m = p[i - 1].x_m + f * (p[i].x_m - p[i - 1].x_m);
      pose.z_m = p[i - 1].z_m + f * (p[i].z_m - p[i - 1].z_m);
      pose.dir_x = heading.x;
      pose.dir_z = heading.z;
      return pose;
    }
  }
  return pose;
}

}  // namespace ocean::model
