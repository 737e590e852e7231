// R2cTransform: one FFTW single-precision real-to-complex 2-D plan for an n_z x n_x grid (z rows)
// on its own buffers, made with FFTW_ESTIMATE so every process picks the same algorithm (as
// C2rTransform). Unnormalised: out = sum in e^{-ikx}, the half spectrum n_z x (n_x / 2 + 1).
#pragma once

#include "c2r_transform.hpp"

namespace ocean::sim {

class R2cTransform {
 public:
  R2cTransform(int n_x, int n_z);
  ~R2cTransform();
  R2cTransform(const R2cTransform&) = delete;
  R2cTransform& operator=(const R2cTransform&) = delete;

  float* input() { return input_.get(); }  // n_z x n_x, row-major; execute() may overwrite it
  const fftwf_complex* output() const { return output_.get(); }
  void execute();

 private:
  int n_x_, n_z_;
  FftwArray<float> input_;
  FftwArray<fftwf_complex> output_;
  fftwf_plan plan_ = nullptr;
};

}  // namespace ocean::sim
