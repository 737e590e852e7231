// Config text must be ASCII. toml++ 3.3 (Debian 12) has undefined behaviour on malformed UTF-8
// and on many valid non-ASCII characters where whitespace may stand (its generated
// is_non_ascii_horizontal_whitespace reaches TOML_UNREACHABLE for e.g. U+00E9 or U+FEEF; both
// found by fuzz_config_toml), so such text is refused before the parser sees it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace ocean::server {

// The offset of the first byte that is not 7-bit ASCII; nullopt if there is none.
std::optional<std::size_t> first_non_ascii(std::string_view text);

}  // namespace ocean::server
