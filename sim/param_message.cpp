// Shortest round-trip printing of parameter values for error messages.
#include "param_message.hpp"

#include <charconv>
#include <cmath>

namespace ocean::sim {

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc{} ? std::string(buf, end) : std::string("?");
}

std::string format_value(long long value) { return std::to_string(value); }

}  // namespace ocean::sim
