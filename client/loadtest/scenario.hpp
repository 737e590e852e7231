// Scenario: a named set of load-test flags (profile, transport, link, announced bandwidth) for a
// network we care about, and what the server must be started with for it; SCENARIOS.md documents
// the same table. Explicit flags override a scenario's values.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace ocean::loadtest {

// What the server must run with for a scenario. ocean-loadtest cannot configure a server it did
// not start: client/loadtest/local_server.py reads these (`ocean-loadtest --list-scenarios
// --json`) and starts one so; against another server the load test warns when the Welcome
// shows a different tick rate or epoch.
struct ServerNeeds {
  int tick_rate_hz = 0;         // --tick-rate; 0 = the server's default
  int epoch_days_ago = 0;       // --epoch this many days before now; 0 = the server's default
  std::string_view schedule;    // a [[schedule]] generator in local_server.py (SCHEDULES); "" = none
  std::string_view profiles;    // --profiles; "" = the server's default
  // A fleet of vessels, client/loadtest/fleets/<fleet>.toml given as --config; "" = none. `vessels`
  // is how many it has (the Welcome must name as many).
  std::string_view fleet;
  int vessels = 0;
  bool any() const { return tick_rate_hz || epoch_days_ago || !schedule.empty() || !profiles.empty() || !fleet.empty(); }
};

struct Scenario {
  std::string_view name;
  std::string_view profile;    // protocol/profile.hpp name
  std::string_view transport;  // "udp", "tcp" or "ws"
  std::string_view link;       // LinkSpec text; "" = no impairment
  std::string_view why;        // the network it stands for
  std::string_view bandwidth = {};  // announced in the Hello (parse_rate_bps); "" = the link's rate
  ServerNeeds server = {};
};

std::span<const Scenario> all_scenarios();
const Scenario* find_scenario(std::string_view name);  // nullptr when unknown

// What the scenario's clients announce: its bandwidth, else its link's rate (0 = unstated).
std::uint64_t announced_bandwidth_bps(const Scenario& s);
// "tick-rate=240 epoch=now-4018d schedule=weather-front profiles=lite"; "" when it needs nothing.
std::string describe(const ServerNeeds& needs);
// "" when a server's Welcome (tick rate, epoch) fits the needs; otherwise what differs. An epoch
// fits within two days of the one asked for. A schedule cannot be seen in a Welcome.
std::string server_mismatch(const ServerNeeds& needs, int tick_rate_hz, std::int64_t epoch_unix_ms, double now_unix_s,
                            std::size_t vessels = 0);

}  // namespace ocean::loadtest
