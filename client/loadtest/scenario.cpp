#include "scenario.hpp"

namespace ocean::loadtest {
namespace {

constexpr Scenario kScenarios[] = {
    {"mobile-3g", "mobile", "udp", "rate=256kbit,delay=80ms,jitter=20ms,loss=5%",
     "a phone on a congested 3G cell: thin pipe, long and varying delay, steady loss"},
    {"lossy-wifi", "mobile", "udp", "delay=10ms,jitter=8ms,loss=10%,reorder=2%,dup=1%",
     "a handheld on busy Wi-Fi: short delay but bursty loss, reordering and duplicates"},
    {"desktop-lan", "desktop", "udp", "",
     "a desktop on a wired LAN: the full 256x256 stream with no impairment"},
    {"tcp-fallback", "mobile", "tcp", "rate=1mbit,delay=40ms",
     "a network that blocks UDP: frames over TCP, whose losses show up as delay"},
    {"flaky-edge", "mobile", "udp", "rate=128kbit,delay=150ms,jitter=60ms,loss=15%,reorder=5%,dup=2%",
     "the worst link we promise to survive: EDGE-class rate, heavy jitter and loss"},
};

}  // namespace

std::span<const Scenario> all_scenarios() { return kScenarios; }

const Scenario* find_scenario(std::string_view name) {
  for (const Scenario& s : kScenarios)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace ocean::loadtest
