// Scenario: a named set of load-test flags (profile, transport, link, announced bandwidth) for a
// network we care about, and what the server must be started with for it; SCENARIOS.md documents
// the same table. Explicit flags override a scenario's values.
#pragma once

#include <span>
#include <string_view>

namespace ocean::loadtest {

struct Scenario {
  std::string_view name;
  std::string_view profile;    // protocol/profile.hpp name
  std::string_view transport;  // "udp" or "tcp"
  std::string_view link;       // LinkSpec text; "" = no impairment
  std::string_view why;        // the network it stands for
  std::string_view bandwidth = {};  // announced in the Hello (parse_rate_bps); "" = the link's rate
};

std::span<const Scenario> all_scenarios();
const Scenario* find_scenario(std::string_view name);  // nullptr when unknown

}  // namespace ocean::loadtest
