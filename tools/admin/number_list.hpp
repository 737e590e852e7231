// A flag's value as exactly `count` comma-separated finite numbers ("40,-60"), nothing else.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace ocean::admin {

inline bool parse_numbers(const std::string& text, std::size_t count, std::vector<double>& out) {
  out.clear();
  if (text.empty() || text.back() == ',') return false;  // "1,2," is not two numbers
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size() || !std::isfinite(out.back())) return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return out.size() == count;
}

}  // namespace ocean::admin
