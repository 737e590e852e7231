// AckWindow: the reliable/yojimbo acknowledgement of complete frames - the latest tick plus a
// bit for each of the 32 ticks before it - kept by codec::Decoder as frames complete and age out,
// or built from any set of ticks, and read back by the server.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "tick.hpp"

namespace ocean::protocol {

inline constexpr std::uint32_t kAckWindowTicks = 32;

struct AckWindow {
  Tick latest_tick = 0;
  std::uint32_t bits = 0;  // bit i (LSB = 0) set: tick latest_tick - 1 - i is complete too

  // True when tick is latest_tick or one of the 32 ticks before it with its bit set.
  bool contains(Tick tick) const {
    if (tick > latest_tick) return false;
    const Tick age = latest_tick - tick;
    return age == 0 || (age <= kAckWindowTicks && ((bits >> (age - 1)) & 1u));
  }

  // The same window after tick completes too (a tick older than the window changes nothing).
  AckWindow with(Tick tick) const {
    if (tick > latest_tick) {
      const Tick shift = tick - latest_tick;
      const std::uint64_t moved = shift > kAckWindowTicks ? 0 : (std::uint64_t{bits} << shift) | (1ull << (shift - 1));
      return AckWindow{tick, static_cast<std::uint32_t>(moved)};
    }
    const Tick age = latest_tick - tick;
    if (age == 0 || age > kAckWindowTicks) return *this;
    return AckWindow{latest_tick, bits | (1u << (age - 1))};
  }

  // The same window after tick is no longer held (the latest tick itself cannot be dropped).
  AckWindow without(Tick tick) const {
    const Tick age = tick < latest_tick ? latest_tick - tick : 0;
    if (age == 0 || age > kAckWindowTicks) return *this;
    return AckWindow{latest_tick, bits & ~(1u << (age - 1))};
  }

  bool operator==(const AckWindow&) const = default;
};

// The window of a set of complete ticks in any order; nullopt when the set is empty.
inline std::optional<AckWindow> ack_window(std::span<const Tick> complete_ticks) {
  if (complete_ticks.empty()) return std::nullopt;
  AckWindow window{complete_ticks.front(), 0};
  for (Tick tick : complete_ticks) window = window.with(tick);
  return window;
}

}  // namespace ocean::protocol
