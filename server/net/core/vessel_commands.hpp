// Vessel commands: an admin's add, course, remove or drop (ParamChange.vessel) turned into the
// fleet every decoder predicts from. A command changes nothing before its tick: it ends the
// presence of a vessel's current track there and starts a new track there (model::Presence), so
// the new fleet presses on the water exactly as the old one did before it, and the wake history
// everyone holds stays right. Tracks that ended before the epoch before last press on nothing the
// wake still holds and are dropped, so the fleet stays within the protocol's 32. Pure: ticks are
// arguments.
#pragma once

#include "message_types.hpp"
#include "tick.hpp"
#include "vessel_track.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ocean::server {

struct FleetRules {
  double square_x_m = -256.0, square_z_m = -256.0, square_size_m = 512.0;  // the wake's square
  int tick_rate_hz = 30;
  std::int64_t epoch_ticks = 1800;
};

struct FleetChange {
  std::vector<model::VesselTrack> fleet;  // the whole fleet from the command's tick on
  std::string error;                      // empty, or why the command is refused
};

// `fleet` as it is, the command taking effect at tick `from` (announced ahead), `now` the
// server's tick.
FleetChange apply_vessel_command(const std::vector<model::VesselTrack>& fleet, const protocol::VesselCommand& command,
                                 Tick from, Tick now, const FleetRules& rules);

// The fleet inside the wake's square and the protocol's limits: empty, or what is wrong.
std::string validate_fleet(const std::vector<model::VesselTrack>& fleet, const FleetRules& rules);

}  // namespace ocean::server
