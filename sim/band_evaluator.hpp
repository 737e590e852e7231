// BandEvaluator: the per-tick work for one n_x x n_z band of the spectrum -- advance every mode to
// time t, form the spectra of heights, slopes, choppy displacement and its derivatives, and
// inverse-transform each into a Frame. The full grid is simply the band of the grid's own size.
#pragma once

#include "c2r_transform.hpp"
#include "frame.hpp"
#include "mode_table.hpp"

namespace ocean::sim {

struct FrameRequest;

class BandEvaluator {
 public:
  BandEvaluator(ModeTable modes, double choppiness, double patch_x_m, double patch_z_m);

  int n_x() const { return modes_.n_x; }
  int n_z() const { return modes_.n_z; }
  const ModeTable& modes() const { return modes_; }

  void evaluate(double t, Frame& out, const FrameRequest& request);

  // Inverse FFTs one evaluate() with this request executes (1 height, 2 slopes, 5 choppy).
  static int transform_count(const FrameRequest& request);

  // Benchmark hook: exactly the FFTW executions of one evaluate(), into the same destinations (the
  // frame's fields, which must come from evaluate() with the same request), with nothing else, so the
  // rest of a tick can be measured against them. The inputs are whatever the previous transforms
  // left: FFTW's run time does not depend on the values.
  void execute_transforms_only(Frame& out, const FrameRequest& request);

 private:
  ModeTable modes_;
  float lambda_;
  double patch_x_m_;
  double patch_z_m_;
  C2rTransform fft_;
  FftwArray<fftwf_complex> spectrum_h_;  // h(k, t), consumed last by the height transform
  FftwArray<fftwf_complex> work_[3];     // derived spectra, up to three per pass
};

}  // namespace ocean::sim
