// Small statistics of a sampled field that several sim tests hold their checks against.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace ocean::sim::test {

inline double max_abs(const std::vector<float>& v) {
  double m = 0.0;
  for (float x : v) m = std::max(m, std::fabs(double(x)));
  return m;
}

}  // namespace ocean::sim::test
