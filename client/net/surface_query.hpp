// SurfaceQuery: the sea a client decoded, at any world point - the height and normal of the water
// there, as the viewer draws it (every lattice summed: the repeating tile, a coarse cascade, the
// wake on its own square), for client code that must sit things on the water: a hull's buoyancy,
// a camera that must not dip under a crest. On a choppy stream the water at a point came from
// elsewhere (each sample is displaced sideways): the query finds where, by the fixed-point steps
// p <- x - D(p) the best engines use, so the height is the one drawn at x, not the one sampled
// there. Pure: the channels are an argument.
#pragma once

#include "frame_channels.hpp"
#include "stream_config.hpp"

#include <array>
#include <vector>

namespace ocean::client {

class SurfaceQuery {
 public:
  // The stream's lattices (StreamConfig::lattices) and where the wake's square lies.
  explicit SurfaceQuery(const codec::StreamConfig& config);

  struct Point {
    double height_m = 0.0;
    std::array<double, 3> normal{0.0, 1.0, 0.0};  // unit, y up
    double source_x_m = 0.0, source_z_m = 0.0;    // where the water at the point came from
  };
  // The surface at world (x, z) in `frame` (a frame's channels, or a blend of two).
  Point at(const FrameChannels& frame, double x_m, double z_m) const;
  double height_at(const FrameChannels& frame, double x_m, double z_m) const { return at(frame, x_m, z_m).height_m; }
  std::array<double, 3> normal_at(const FrameChannels& frame, double x_m, double z_m) const {
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
  double sum(const std::vector<float>& channel, double x_m, double z_m) const;

  std::vector<Lattice> lattices_;
};

}  // namespace ocean::client
