#include "scenario_listing.hpp"

#include <cstdio>

#include "scenario.hpp"

namespace ocean::loadtest {
namespace {

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string bandwidth_text(const Scenario& s) {
  const std::uint64_t bps = announced_bandwidth_bps(s);
  return bps ? std::to_string(bps / 1000) + "kbit" : "-";
}

}  // namespace

void print_scenarios(std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line, "%-14s %-8s %-9s %-64s %-9s %-30s %s\n", "scenario", "profile", "transport", "link",
                "bandwidth", "server", "stands for");
  out << line;
  for (const Scenario& s : all_scenarios()) {
    const std::string server = describe(s.server);
    std::snprintf(line, sizeof line, "%-14.*s %-8.*s %-9.*s %-64.*s %-9s %-30s %.*s\n", int(s.name.size()), s.name.data(),
                  int(s.profile.size()), s.profile.data(), int(s.transport.size()), s.transport.data(),
                  int(s.link.empty() ? 4 : s.link.size()), s.link.empty() ? "none" : s.link.data(),
                  bandwidth_text(s).c_str(), server.empty() ? "default" : server.c_str(), int(s.why.size()), s.why.data());
    out << line;
  }
}

std::string scenarios_json() {
  std::string j = "[";
  for (const Scenario& s : all_scenarios()) {
    if (j.size() > 1) j += ",";
    j += "{\"name\":" + quoted(s.name) + ",\"profile\":" + quoted(s.profile) + ",\"transport\":" + quoted(s.transport) +
         ",\"link\":" + quoted(s.link) + ",\"bandwidth_bps\":" + std::to_string(announced_bandwidth_bps(s)) +
         ",\"server\":{\"tick_rate_hz\":" + std::to_string(s.server.tick_rate_hz) +
         ",\"epoch_days_ago\":" + std::to_string(s.server.epoch_days_ago) + ",\"schedule\":" + quoted(s.server.schedule) +
         ",\"profiles\":" + quoted(s.server.profiles) + ",\"fleet\":" + quoted(s.server.fleet) +
         ",\"vessels\":" + std::to_string(s.server.vessels) + "},\"why\":" + quoted(s.why) + "}";
  }
  return j + "]";
}

}  // namespace ocean::loadtest
