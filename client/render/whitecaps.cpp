#include "client/render/whitecaps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocean::render {

std::span<const float> Whitecaps::shade(std::span<const float> jacobian, int n, float patch_x_m, float patch_z_m,
                                        double dt_s) {
  const std::size_t tile = static_cast<std::size_t>(std::max(n, 0)) * std::max(n, 0);
  if (tile == 0 || jacobian.size() < tile) return jacobian;
  const std::span<const float> tile_j = jacobian.first(tile);
  const std::span<const float> past = field_.advance(n, patch_x_m, patch_z_m, wind_, dt_s);
  shading_ = cover_.update(tile_j, past, dt_s);
  // No wind (or none known yet: the first frames may come before the scene's) whitens nothing.
  const bool windless = WhitecapCover::observed(wind_.speed_mps) <= 0.0;
  ramp_.resize(tile);
  for (std::size_t i = 0; i < tile; ++i)
    ramp_[i] = windless ? 0.0f : std::clamp((shading_.threshold - tile_j[i]) / shading_.band, 0.0f, 1.0f);
  const std::vector<float>& foam = field_.add(ramp_);
  shading_.cover = static_cast<float>(field_.mean());
  shading_.wind_x = static_cast<float>(std::cos(wind_.dir_deg * std::numbers::pi / 180.0));
  shading_.wind_z = static_cast<float>(std::sin(wind_.dir_deg * std::numbers::pi / 180.0));
  shaded_.assign(jacobian.begin(), jacobian.end());
  std::copy(foam.begin(), foam.end(), shaded_.begin());
  return shaded_;
}

}  // namespace ocean::render
