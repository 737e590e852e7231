// A flag's value as exactly `count` comma-separated numbers ("40,-60"), nothing else.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace ocean::admin {

inline bool parse_numbers(const std::string& text, std::size_t count, std::vector<double>& out) {
  out.clear();
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size()) return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return out.size() == count;
}

}  // namespace ocean::admin
