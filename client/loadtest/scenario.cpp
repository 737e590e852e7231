#include "scenario.hpp"

#include <cmath>

#include "link_spec.hpp"

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
    {"browser-3g", "mobile", "ws", "rate=1mbit,delay=75ms,loss=1%",
     "a phone's browser on 3G: WebSocket (give --server the --ws-listen port), 150 ms round trip, 1 % loss below TCP"},
    {"flaky-edge", "mobile", "udp", "rate=128kbit,delay=150ms,jitter=60ms,loss=15%,reorder=5%,dup=2%",
     "the worst link we promise to survive: EDGE-class rate, heavy jitter and loss"},
    {"edge-2g", "mobile", "udp", "rate=32kbit,delay=300ms,jitter=50ms,loss=3%",
     "a phone on a 2G EDGE cell: a 32 kbit/s pipe, long delay; the first frame must come within 2 s"},
    {"gprs", "lite", "udp", "rate=16kbit,delay=300ms,jitter=50ms,loss=2%",
     "the thinnest link we stream to: GPRS, 16 kbit/s, the lite profile", {}, {0, 0, {}, "mobile,desktop,lite", {}, 0}},
    {"weather-front", "mobile", "udp", "rate=256kbit,delay=80ms,jitter=20ms,loss=2%",
     "a 3G phone while the weather changes every 2.5 s: every scene key, depth and spectrum included",
     {}, {0, 0, "weather-front", {}, {}, 0}},
    {"old-epoch", "mobile", "udp", "delay=20ms",
     "a fleet whose epoch is 11 years back, ticking at 240 Hz: ticks beyond 32 bits",
     {}, {240, 4018, {}, {}, {}, 0}},
    {"harbour", "mobile", "udp", "rate=32kbit,delay=300ms,jitter=50ms,loss=3%",
     "8 vessels and their wakes (the server's sea), phones on a 2G EDGE cell", {}, {0, 0, {}, {}, "harbour", 8}},
    {"regatta", "desktop-choppy", "udp", "",
     "16 yachts racing, desktops on a LAN with the choppy profile", {}, {0, 0, {}, "mobile,desktop-choppy", "regatta", 16}},
    {"man-overboard", "mobile", "udp", "rate=256kbit,delay=80ms,jitter=20ms,loss=2%",
     "things going over the side (8 objects' splashes, every 6 s) beside a ship and a rescue launch, 3G phones",
     {}, {0, 0, {}, {}, "man-overboard", 10}},
};

}  // namespace

std::span<const Scenario> all_scenarios() { return kScenarios; }

const Scenario* find_scenario(std::string_view name) {
  for (const Scenario& s : kScenarios)
    if (s.name == name) return &s;
  return nullptr;
}

std::uint64_t announced_bandwidth_bps(const Scenario& s) {
  if (!s.bandwidth.empty()) return static_cast<std::uint64_t>(std::llround(parse_rate_bps(s.bandwidth).value_or(0.0)));
  return static_cast<std::uint64_t>(std::llround(parse_link_spec(s.link).spec.rate_bps));
}

std::string describe(const ServerNeeds& n) {
  std::string out;
  auto add = [&](const std::string& item) { out += (out.empty() ? "" : " ") + item; };
  if (n.tick_rate_hz) add("tick-rate=" + std::to_string(n.tick_rate_hz));
  if (n.epoch_days_ago) add("epoch=now-" + std::to_string(n.epoch_days_ago) + "d");
  if (!n.schedule.empty()) add("schedule=" + std::string(n.schedule));
  if (!n.profiles.empty()) add("profiles=" + std::string(n.profiles));
  if (!n.fleet.empty()) add("fleet=" + std::string(n.fleet) + " (" + std::to_string(n.vessels) + " vessels)");
  return out;
}

}  // namespace ocean::loadtest

namespace ocean::loadtest {

std::string server_mismatch(const ServerNeeds& n, int tick_rate_hz, std::int64_t epoch_unix_ms, double now_unix_s,
                            std::size_t vessels) {
  std::string out;
  if (n.tick_rate_hz && n.tick_rate_hz != tick_rate_hz)
    out += "it ticks at " + std::to_string(tick_rate_hz) + " Hz, not " + std::to_string(n.tick_rate_hz);
  const double days_ago = (now_unix_s - static_cast<double>(epoch_unix_ms) / 1000.0) / 86400.0;
  if (n.epoch_days_ago && std::fabs(days_ago - n.epoch_days_ago) > 2.0)
    out += (out.empty() ? "" : "; ") + std::string("its epoch is ") + std::to_string(std::lround(days_ago)) +
           " days ago, not " + std::to_string(n.epoch_days_ago);
  if (n.vessels && static_cast<std::size_t>(n.vessels) != vessels)
    out += (out.empty() ? "" : "; ") + std::string("it runs ") + std::to_string(vessels) + " vessels, not " +
           std::to_string(n.vessels);
  return out;
}

}  // namespace ocean::loadtest
