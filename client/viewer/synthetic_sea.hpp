// A stand-in for the server's stream in ocean-viewer-local and the render tests: a sum of
// analytic Gerstner waves whose wave vectors sit on the patch's Fourier lattice, so the field is
// exactly periodic and tiles like the real spectral patch. Pure: time is an argument.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ocean::viewer {

struct SyntheticSeaParams {
  int n = 64;                     // samples per side
  float patch_m = 128.0f;         // patch width and depth, metres
  int wave_count = 14;
  float wind_direction_rad = 0.6f;  // direction the waves travel toward, from +x toward +z
  float steepness = 0.8f;         // sum of a*k over all waves; near 1 the crests fold (foam)
  bool choppy = true;             // produce displacement and Jacobian
  std::uint32_t seed = 1;
};

// Same layout as render::FrameStreams: n x n, row-major, rows along +z.
struct SeaFrame {
  int n = 0;
  std::vector<float> height, slope_x, slope_z, disp_x, disp_z, jacobian;
};

class SyntheticSea {
 public:
  // Throws std::invalid_argument naming the parameter when params are out of range.
  explicit SyntheticSea(const SyntheticSeaParams& params);

  void evaluate(double time_s, SeaFrame& out) const;
  const SyntheticSeaParams& params() const { return params_; }
  float max_amplitude_m() const;  // sum of the wave amplitudes: a bound on |height|

 private:
  struct Wave {
    float kx, kz, k;      // rad/m, on the lattice 2*pi*(m, l)/patch
    float amplitude;      // metres
    double omega;         // deep-water dispersion sqrt(g k), rad/s
    float phase;
  };
  SyntheticSeaParams params_;
  std::vector<Wave> waves_;
};

}  // namespace ocean::viewer
