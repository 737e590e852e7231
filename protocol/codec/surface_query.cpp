#include "surface_query.hpp"

#include <cmath>

namespace ocean::codec {

SurfaceQuery::SurfaceQuery(const StreamConfig& config) {
  for (const StreamConfig::Lattice& l : config.lattices()) {
    // The sea's lattices repeat from the world's origin; the wake lies once on its square.
    const double ox = l.wake ? config.wake.origin_x_m : 0.0, oz = l.wake ? config.wake.origin_z_m : 0.0;
    lattices_.push_back({l.n, l.patch_x_m, l.patch_z_m, ox, oz, l.wake, l.samples_at});
  }
}

double SurfaceQuery::sum(std::span<const float> channel, double x_m, double z_m, Lattices which) const {
  if (channel.empty()) return 0.0;
  double total = 0.0;
  for (const Lattice& l : lattices_) {
    if (l.bounded && which == Lattices::sea) continue;
    const double u = (x_m - l.origin_x_m) / l.size_x_m, v = (z_m - l.origin_z_m) / l.size_z_m;
    if (l.bounded && !(u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0)) continue;
    // Sample coordinates, wrapped into the period (the fields are periodic: a Fourier lattice).
    const double su = (u - std::floor(u)) * l.n, sv = (v - std::floor(v)) * l.n;
    const int i0 = static_cast<int>(su) % l.n, j0 = static_cast<int>(sv) % l.n;
    const int i1 = (i0 + 1) % l.n, j1 = (j0 + 1) % l.n;
    const double fu = su - std::floor(su), fv = sv - std::floor(sv);
    const auto at = [&](int i, int j) {
      return static_cast<double>(channel[l.samples_at + static_cast<std::size_t>(j) * l.n + i]);
    };
    total += (1.0 - fv) * ((1.0 - fu) * at(i0, j0) + fu * at(i1, j0)) + fv * ((1.0 - fu) * at(i0, j1) + fu * at(i1, j1));
  }
  return total;
}

SurfaceQuery::Point SurfaceQuery::at(const SurfaceFields& frame, double x_m, double z_m, Lattices which) const {
  Point p;
  p.source_x_m = x_m;
  p.source_z_m = z_m;
  if (!frame.disp_x.empty()) {
    // The water drawn at x left p with p + D(p) = x.
    for (int step = 0; step < kInversionSteps; ++step) {
      const double dx = sum(frame.disp_x, p.source_x_m, p.source_z_m, which), dz = sum(frame.disp_z, p.source_x_m, p.source_z_m, which);
      p.source_x_m = x_m - dx;
      p.source_z_m = z_m - dz;
    }
  }
  p.height_m = sum(frame.height, p.source_x_m, p.source_z_m, which);
  const double sx = sum(frame.slope_x, p.source_x_m, p.source_z_m, which), sz = sum(frame.slope_z, p.source_x_m, p.source_z_m, which);
  const double length = std::sqrt(sx * sx + 1.0 + sz * sz);
  p.normal = {-sx / length, 1.0 / length, -sz / length};
  return p;
}

}  // namespace ocean::codec
