#include "client/render/lod.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {

int lod_level_for_distance(float distance_m, const LodPolicy& policy) {
  if (!(distance_m >= policy.lod0_distance_m) || policy.lod0_distance_m <= 0.0f) return 0;
  const int level = 1 + static_cast<int>(std::floor(std::log2(distance_m / policy.lod0_distance_m)));
  return std::clamp(level, 0, std::max(policy.max_level, 0));
}

int supported_lod_levels(int grid_n, int wanted_max_level) {
  int level = 0;
  while (level < wanted_max_level && grid_n % (1 << (level + 1)) == 0) ++level;
  return level;
}

}  // namespace ocean::render
