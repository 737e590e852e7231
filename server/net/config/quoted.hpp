// quoted(): a value in single quotes, the one way option values are shown in error messages.
#pragma once

#include <string>
#include <string_view>

namespace ocean::server {

// Built by appending: g++ 12 at -O2 warns (-Wrestrict, falsely) on "'" + std::string(...).
inline std::string quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '\'';
  out.append(text);
  out += '\'';
  return out;
}

}  // namespace ocean::server
