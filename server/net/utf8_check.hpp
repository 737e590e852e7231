// Strict UTF-8 validation (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
// toml++ 3.3 (Debian 12) misbehaves on malformed UTF-8, so config text is checked before parsing.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace ocean::server {

// The byte offset of the first byte that does not start a valid UTF-8 sequence; nullopt if valid.
std::optional<std::size_t> first_invalid_utf8(std::string_view text);

}  // namespace ocean::server
