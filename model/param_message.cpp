// Shortest round-trip printing of parameter values for error messages.
#include "param_message.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ocean::model {

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
#if defined(__cpp_lib_to_chars)
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc{} ? std::string(buf, end) : std::string("?");
#else
  // The browser viewer's libc++ (Emscripten 3.1) has no floating-point to_chars: the fewest %g
  // digits that read back as the same double.
  for (int digits = 1; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
#endif
}

std::string format_value(long long value) { return std::to_string(value); }

}  // namespace ocean::model
