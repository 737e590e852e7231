// bad_param(): the one wording of every parameter error: "<name> = <value> is invalid: allowed <range>".
// Values print in shortest round-trip form so the message shows exactly what was passed.
#pragma once

#include <string>
#include <string_view>

namespace ocean::model {

std::string format_value(double value);
std::string format_value(long long value);

inline std::string bad_param(std::string_view name, double value, std::string_view allowed) {
  return std::string(name) + " = " + format_value(value) + " is invalid: allowed " + std::string(allowed);
}

inline std::string bad_param(std::string_view name, int value, std::string_view allowed) {
  return std::string(name) + " = " + format_value(static_cast<long long>(value)) + " is invalid: allowed " +
         std::string(allowed);
}

}  // namespace ocean::model
