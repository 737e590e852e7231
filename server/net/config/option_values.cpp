#include "option_values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace ocean::server {

std::string parse_seed(std::string_view text, std::uint64_t& out) {
  const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  const std::string_view digits = hex ? text.substr(2) : text;
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, hex ? 16 : 10);
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
    return quoted(text) + " is not an unsigned 64-bit integer (0..18446744073709551615, decimal or 0x hex)";
  out = value;
  return {};
}

std::string parse_number(std::string_view text, double& out) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return quoted(text) + " is not a number";
  if (!std::isfinite(value)) return quoted(text) + " must be a finite number";
  out = value;
  return {};
}

std::string show_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string trim(std::string text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

bool read_file(const std::string& path, std::string& contents) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  contents = buffer.str();
  return static_cast<bool>(in) || in.eof();
}

std::string apply_address(std::optional<ListenAddress>& target, std::string_view value, bool allow_off) {
  if (allow_off && value == "off") {
    target.reset();
    return {};
  }
  std::string error;
  target = parse_listen_address(value, error);
  return error;
}

std::string apply_address(std::map<std::string, ListenAddress, std::less<>>& by_name, std::string_view name,
                          std::string_view value) {
  std::optional<ListenAddress> address;
  if (std::string error = apply_address(address, value, true); !error.empty()) return error;
  if (address)
    by_name.insert_or_assign(std::string(name), *address);
  else if (const auto found = by_name.find(name); found != by_name.end())
    by_name.erase(found);
  return {};
}

std::string show_optional_address(const std::optional<ListenAddress>& address, const char* absent) {
  return address ? address->to_string() : absent;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ",") + item;
  return out;
}

std::vector<std::string> split_list(std::string_view v) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= v.size()) {
    const std::size_t comma = std::min(v.find(',', start), v.size());
    if (std::string item = trim(std::string(v.substr(start, comma - start))); !item.empty()) items.push_back(item);
    start = comma + 1;
  }
  return items;
}

}  // namespace ocean::server
