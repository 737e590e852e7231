#include "vessel_commands.hpp"

#include "param_message.hpp"
#include "server_config.hpp"
#include "wire_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ocean::server {
namespace {

constexpr double kDropSplashS = 1.0;
const double kMaxSpeedMps = model::TrackLimits{}.max_speed_mps;

std::string named(std::uint32_t id) { return "vessel " + std::to_string(id); }

bool repeats(const model::Presence& p) { return p.every_s > 0.0; }

// A dropped object presses for a splash (once or again and again); a vessel until it is steered
// or removed (its current track is open-ended).
bool is_object(const model::Presence& p) { return repeats(p) || std::isfinite(p.for_s); }

// When a track stops pressing for good (infinity: never).
double end_of(const model::Presence& p) {
  if (repeats(p) || p.for_s == std::numeric_limits<double>::infinity()) return std::numeric_limits<double>::infinity();
  return p.from_s + p.for_s;
}

// The track of `id` pressing at the step from tick `from` (its middle), if any.
const model::VesselTrack* present(const std::vector<model::VesselTrack>& fleet, std::uint32_t id, double mid_s) {
  for (const model::VesselTrack& v : fleet)
    if (v.id == id && model::present_at(v.presence, mid_s)) return &v;
  return nullptr;
}

// Whether a track of `id` still presses at or after from_s (or has yet to): the id is taken.
bool id_taken(const std::vector<model::VesselTrack>& fleet, std::uint32_t id, double from_s) {
  return std::any_of(fleet.begin(), fleet.end(), [&](const model::VesselTrack& v) { return v.id == id && end_of(v.presence) > from_s; });
}

// Ends `track` at from_s (a track that has not begun by then is dropped: false).
bool end_at(model::VesselTrack& track, double from_s) {
  if (track.presence.from_s == -std::numeric_limits<double>::infinity()) track.presence.from_s = 0.0;  // no tick is earlier
  track.presence.for_s = from_s - track.presence.from_s;
  return track.presence.for_s > 0.0;
}

// A hull from (x, z), waiting there until from_s, then sailing `heading_deg` at `speed` until the
// square's edge, where it stops.
model::VesselTrack sailing(std::uint32_t id, const model::Hull& hull, double x, double z, double heading_deg,
                           double speed, double from_s, const FleetRules& rules) {
  model::VesselTrack v;
  v.id = id;
  v.hull = hull;
  v.points = {{0.0, x, z}};
  v.presence = {from_s, std::numeric_limits<double>::infinity(), 0.0};
  const double a = heading_deg * std::numbers::pi / 180.0, dx = std::cos(a), dz = std::sin(a);
  // How far it sails before leaving the square, along (dx, dz).
  double reach = std::numeric_limits<double>::infinity();
  const auto limit = [&](double p, double d, double lo, double hi) {
    if (d > 1e-12) reach = std::min(reach, (hi - p) / d);
    if (d < -1e-12) reach = std::min(reach, (lo - p) / d);
  };
  limit(x, dx, rules.square_x_m, rules.square_x_m + rules.square_size_m);
  limit(z, dz, rules.square_z_m, rules.square_z_m + rules.square_size_m);
  if (speed > 0.0 && reach > 1.0 && std::isfinite(reach)) {
    const model::Waypoint start{from_s, x, z};
    // On the square's edge exactly: x + reach dx may round a hair outside it.
    model::Waypoint end{from_s + reach / speed,
                        std::clamp(x + reach * dx, rules.square_x_m, rules.square_x_m + rules.square_size_m),
                        std::clamp(z + reach * dz, rules.square_z_m, rules.square_z_m + rules.square_size_m)};
    // Times near 1e7 s round too: the leg, as validate_fleet measures it (in the square's own
    // coordinates), must not come out a hair faster than asked (20 m/s would be refused).
    const auto leg_speed = [&] {
      return std::hypot((end.x_m - rules.square_x_m) - (start.x_m - rules.square_x_m),
                        (end.z_m - rules.square_z_m) - (start.z_m - rules.square_z_m)) / (end.t_s - start.t_s);
    };
    while (leg_speed() > speed) end.t_s = std::nextafter(end.t_s, std::numeric_limits<double>::infinity());
    v.points.push_back(start);
    v.points.push_back(end);
  }
  return v;
}

// The fleet without what no tick the wake still holds was pressed by: tracks that ended before
// the epoch before last.
std::vector<model::VesselTrack> remembered(const std::vector<model::VesselTrack>& fleet, Tick now, const FleetRules& rules) {
  const auto epoch = static_cast<std::int64_t>(now) / rules.epoch_ticks;
  const double forgotten_s = static_cast<double>(std::max<std::int64_t>(0, epoch - 2) * rules.epoch_ticks) /
                             static_cast<double>(rules.tick_rate_hz);
  std::vector<model::VesselTrack> out;
  for (const model::VesselTrack& v : fleet)
    if (!(end_of(v.presence) < forgotten_s)) out.push_back(v);
  return out;
}

}  // namespace

std::string validate_fleet(const std::vector<model::VesselTrack>& fleet, const FleetRules& rules) {
  if (fleet.size() > protocol::kMaxVessels)
    return "at most " + std::to_string(protocol::kMaxVessels) +
           " vessels and objects (counting the tracks of the last two minutes): remove one, or wait";
  for (const model::VesselTrack& v : fleet)
    if (std::string error = validate_in_square(v, rules.square_x_m, rules.square_z_m, rules.square_size_m); !error.empty())
      return error;
  return {};
}

FleetChange apply_vessel_command(const std::vector<model::VesselTrack>& fleet, const protocol::VesselCommand& c, Tick from,
                                 Tick now, const FleetRules& rules) {
  FleetChange out{remembered(fleet, now, rules), {}};
  const double rate = static_cast<double>(rules.tick_rate_hz);
  const double from_s = static_cast<double>(from) / rate, mid_s = (static_cast<double>(from) + 0.5) / rate;
  const model::VesselTrack* current = present(out.fleet, c.id, mid_s);
  const auto find = [&](const model::VesselTrack* track) {
    return std::find_if(out.fleet.begin(), out.fleet.end(), [&](const model::VesselTrack& v) { return &v == track; });
  };
  const bool sails = c.action == wire::VesselAction::add || c.action == wire::VesselAction::course;
  if (sails && !(c.speed_mps >= 0.0 && c.speed_mps <= kMaxSpeedMps))
    return {{}, "speed " + model::format_value(c.speed_mps) + " m/s: must be in [0, " + model::format_value(kMaxSpeedMps) + "]"};
  switch (c.action) {
    case wire::VesselAction::add:
      if (id_taken(out.fleet, c.id, from_s))
        return {{}, named(c.id) + " is already at sea or due (give another id, or set its course)"};
      out.fleet.push_back(sailing(c.id, c.hull, c.x_m, c.z_m, c.heading_deg, c.speed_mps, from_s, rules));
      break;
    case wire::VesselAction::course: {
      if (!current) return {{}, named(c.id) + " is not at sea"};
      if (is_object(current->presence)) return {{}, named(c.id) + " is a dropped object; it cannot be steered"};
      const model::HullPose pose = model::pose_at(*current, from_s);
      const model::Hull hull = current->hull;
      auto it = find(current);
      if (!end_at(*it, from_s)) out.fleet.erase(it);
      out.fleet.push_back(sailing(c.id, hull, pose.x_m, pose.z_m, c.heading_deg, c.speed_mps, from_s, rules));
      break;
    }
    case wire::VesselAction::remove: {
      if (!current) return {{}, named(c.id) + " is not at sea"};
      if (repeats(current->presence))
        return {{}, named(c.id) + " splashes again and again (a config's [[drop]]); change the config to remove it"};
      if (is_object(current->presence)) return {{}, named(c.id) + " is a dropped object; its splash ends by itself"};
      auto it = find(current);
      if (!end_at(*it, from_s)) out.fleet.erase(it);
      break;
    }
    case wire::VesselAction::drop: {
      if (!(c.size_m > 0.0 && c.size_m <= kMaxDropSizeM))
        return {{}, "size " + model::format_value(c.size_m) + " m: must be in (0, " + model::format_value(kMaxDropSizeM) + "]"};
      if (id_taken(out.fleet, c.id, from_s))
        return {{}, named(c.id) + " is already at sea or due (give the object an id of its own)"};
      out.fleet.push_back(dropped_object(c.id, c.size_m, c.x_m, c.z_m, {from_s, kDropSplashS, 0.0}));
      break;
    }
    default:
      return {{}, "VesselCommand.action: add, course, remove or drop"};
  }
  if (std::string error = validate_fleet(out.fleet, rules); !error.empty()) return {{}, error};
  return out;
}

}  // namespace ocean::server
