// SurfaceQuery: a stream's sea at any world point - the height and normal of the water there, as
// a viewer draws it (every lattice summed: the repeating tile, a coarse cascade, the wake on its
// own square), for code that must sit things on the water: a hull's buoyancy, a camera that must
// not dip under a crest, a game server's floating objects. On a choppy stream the water at a point
// came from elsewhere (each sample is displaced sideways): the query finds where, by the
// fixed-point steps p <- x - D(p) the best engines use, so the height is the one drawn at x, not
// the one sampled there. The client asks its decoded frames, the server its true ones (HeightQuery,
// PROTOCOL.md 8): one sampler, so the two differ only by what the stream's bound lets them.
// Pure: the channels are an argument.
#pragma once

#include "stream_config.hpp"

#include <array>
#include <span>
#include <vector>

namespace ocean::codec {

// One moment's channels, every lattice's samples in StreamConfig::lattices order; the displacement
// empty unless the stream is choppy, the slopes empty without normals.
struct SurfaceFields {
  std::span<const float> height, slope_x, slope_z, disp_x, disp_z;
};

// Any frame with the channels' usual names (a client's FrameChannels, the sim's Frame).
template <typename Frame>
SurfaceFields surface_fields(const Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z};
}

class SurfaceQuery {
 public:
  // The stream's lattices (StreamConfig::lattices) and where the wake's square lies.
  explicit SurfaceQuery(const StreamConfig& config);

  struct Point {
    double height_m = 0.0;
    std::array<double, 3> normal{0.0, 1.0, 0.0};  // unit, y up
    double source_x_m = 0.0, source_z_m = 0.0;    // where the water at the point came from
  };
  // Every lattice, or the sea's alone (the wake's left out: a hull rides the waves, not the
  // depression its own pressure makes in the wake lattice).
  enum class Lattices { all, sea };
  // The surface at world (x, z) in `fields` (a frame's channels, or a blend of two).
  Point at(const SurfaceFields& fields, double x_m, double z_m, Lattices which = Lattices::all) const;
  template <typename Frame>
  Point at(const Frame& frame, double x_m, double z_m, Lattices which = Lattices::all) const {
    return at(surface_fields(frame), x_m, z_m, which);
  }
  template <typename Frame>
  double height_at(const Frame& frame, double x_m, double z_m, Lattices which = Lattices::all) const {
    return at(frame, x_m, z_m, which).height_m;
  }
  template <typename Frame>
  std::array<double, 3> normal_at(const Frame& frame, double x_m, double z_m) const {
    return at(frame, x_m, z_m).normal;
  }

  static constexpr int kInversionSteps = 4;  // enough while the Jacobian stays positive (no fold)

 private:
  struct Lattice {
    int n;
    double size_x_m, size_z_m;       // the lattice's period
    double origin_x_m, origin_z_m;   // where its sample (0, 0) lies
    bool bounded;                    // the wake: only inside its square, not repeated
    std::size_t samples_at;
  };
  // The sum over the lattices of one channel at (x, z), bilinear within each.
  double sum(std::span<const float> channel, double x_m, double z_m, Lattices which) const;

  std::vector<Lattice> lattices_;
};

}  // namespace ocean::codec
