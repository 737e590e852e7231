#include "field_extent.hpp"

#include "sea_model.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::sim {

FieldExtent expected_extent(const SceneParams& p) {
  const Spectrum spectrum(p);
  const double dkx = wavenumber(1, p.patch_x_m);
  const double dkz = wavenumber(1, p.patch_z_m);
  double h = 0, sx = 0, sz = 0, dx = 0, dz = 0, dxx = 0, dzz = 0, dxz = 0;
  for (int j = -p.size_z / 2; j < p.size_z / 2; ++j)
    for (int i = -p.size_x / 2; i < p.size_x / 2; ++i) {
      if ((i == 0 && j == 0) || !p.band.keeps(i, j)) continue;
      const double kx = i * dkx, kz = j * dkz, k2 = kx * kx + kz * kz;
      const double v = spectrum.density(kx, kz) * dkx * dkz;  // this mode's share of the variance
      if (!(v > 0.0)) continue;
      h += v;
      sx += kx * kx * v;
      sz += kz * kz * v;
      dx += kx * kx / k2 * v;
      dz += kz * kz / k2 * v;
      dxx += kx * kx * kx * kx / k2 * v;
      dzz += kz * kz * kz * kz / k2 * v;
      dxz += kx * kx * kz * kz / k2 * v;
    }
  const double chop = p.choppiness;
  return FieldExtent{std::sqrt(h), std::sqrt(std::max(sx, sz)), chop * std::sqrt(std::max(dx, dz)),
                     chop * std::sqrt(std::max({dxx, dzz, dxz}))};
}

}  // namespace ocean::sim
