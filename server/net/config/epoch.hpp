// The epoch: the wall-clock instant of tick 0, as Unix milliseconds. Every server started with the
// same epoch and tick rate numbers its ticks identically, so replicas emit the same frame per tick.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ocean::server {

// Accepts an integer number of Unix milliseconds ("0", "1763744400000") or an RFC 3339 timestamp
// ("2026-11-21T17:00:00Z", "2026-11-21T18:00:00.250+01:00"). On failure sets `error`.
std::optional<std::int64_t> parse_epoch_ms(std::string_view text, std::string& error);

}  // namespace ocean::server
