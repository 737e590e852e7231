// Tick: the server's tick count since its epoch (PROTOCOL.md 6). 64 bits everywhere, in memory
// and on the wire, so no legal configuration ever wraps it (at 240 Hz it lasts 2.4 billion years).
#pragma once

#include <cstdint>

namespace ocean {

using Tick = std::uint64_t;

}  // namespace ocean
