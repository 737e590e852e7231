// How an option's text becomes its value and back: numbers, seeds, names from the model's tables,
// listen addresses, comma lists and small files, each failure a message naming the text.
#pragma once

#include "listen_address.hpp"
#include "quoted.hpp"
#include "scene_names.hpp"

#include <charconv>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocean::server {

template <typename Int>
std::string parse_integer(std::string_view text, Int& out) {
  Int value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range)
    return quoted(text) + " is out of range for an integer option";
  if (ec != std::errc() || end != text.data() + text.size()) return quoted(text) + " is not an integer";
  out = value;
  return {};
}

// Any unsigned 64-bit value, decimal or 0x hex: TOML integers stop at 2^63 - 1, so larger seeds
// come as strings.
std::string parse_seed(std::string_view text, std::uint64_t& out);
// A finite number.
std::string parse_number(std::string_view text, double& out);
std::string show_number(double value);  // %g
std::string trim(std::string text);
// Reads a whole small file; false when it cannot be opened.
bool read_file(const std::string& path, std::string& contents);
// A listen address, or (allow_off) "off" for none.
std::string apply_address(std::optional<ListenAddress>& target, std::string_view value, bool allow_off);
std::string show_optional_address(const std::optional<ListenAddress>& address, const char* absent);
// The same, for one name of a map of addresses: "off" takes the name out.
std::string apply_address(std::map<std::string, ListenAddress, std::less<>>& by_name, std::string_view name,
                          std::string_view value);
// Sets target from one of the names in the model's table (scene_names.hpp).
template <typename Kind>
std::string apply_name(Kind& target, std::string_view value, std::optional<Kind> (*from_name)(std::string_view),
                       std::vector<std::string> (*names)()) {
  const std::optional<Kind> kind = from_name(value);
  if (!kind) return quoted(value) + " is not one of " + model::join_names(names());
  target = *kind;
  return {};
}

std::string join(const std::vector<std::string>& items);  // "a,b,c"
// "a, b,,c" -> {"a", "b", "c"}: items trimmed, empty ones left out.
std::vector<std::string> split_list(std::string_view v);

}  // namespace ocean::server
