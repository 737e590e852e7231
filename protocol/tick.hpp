// Tick: the server's tick count since its epoch (PROTOCOL.md 6). 64 bits everywhere, in memory
// and on the wire, so no legal configuration ever wraps it (at 240 Hz it lasts 2.4 billion years).
#pragma once

#include <cstdint>
#include <limits>

namespace ocean {

using Tick = std::uint64_t;

// The widest tick on the wire (a 10-byte varint): what every size bound is checked against.
inline constexpr Tick kLargestTick = std::numeric_limits<Tick>::max();

}  // namespace ocean
