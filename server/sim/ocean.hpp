// Ocean: the Tessendorf spectral ocean. Owns h0(k), w(k) and the FFTW plans; evaluates frames
// at any time t. Pure: no clocks, no I/O, no globals; the frame depends only on (params, t).
#pragma once

#include "frame.hpp"
#include "scene_params.hpp"

#include <memory>

namespace ocean::sim {

struct FrameRequest {
  bool slopes = true;   // exact spectral dh/dx, dh/dz
  bool choppy = false;  // horizontal displacement (scaled by choppiness) and its Jacobian
};

class Ocean {
 public:
  explicit Ocean(const SceneParams& params);  // throws ParamError
  ~Ocean();
  Ocean(Ocean&&) noexcept;
  Ocean& operator=(Ocean&&) noexcept;

  const SceneParams& params() const;

  // The full size_x x size_z frame at time t (seconds).
  void evaluate(double t, Frame& out, FrameRequest request = {});

  // An n_x x n_z frame (powers of two, 16 <= n <= size) made from the central n_x x n_z modes of the
  // same spectrum: the exact low-pass of the full frame, sampled every size/n-th point.
  void evaluate_band(double t, int n_x, int n_z, Frame& out, FrameRequest request = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ocean::sim
