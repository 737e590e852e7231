// C2rTransform: one FFTW single-precision complex-to-real 2-D plan for an n_z x n_x grid (z rows),
// made with FFTW_ESTIMATE on fftwf_malloc'd buffers so every process picks the same algorithm,
// and executed on any input/output of the same alignment. Unnormalised: out = sum in e^{+ikx}.
#pragma once

#include <fftw3.h>

#include <cstddef>
#include <memory>

namespace ocean::sim {

struct FftwFree {
  void operator()(void* p) const { fftwf_free(p); }
};
template <class T>
using FftwArray = std::unique_ptr<T[], FftwFree>;

template <class T>
FftwArray<T> fftw_array(std::size_t count) {
  return FftwArray<T>(static_cast<T*>(fftwf_malloc(sizeof(T) * (count ? count : 1))));
}

// Before any plan is made or destroyed: FFTW then locks its (process-global) planner itself.
void make_fftw_planner_thread_safe();

class C2rTransform {
 public:
  C2rTransform(int n_x, int n_z);
  ~C2rTransform();
  C2rTransform(const C2rTransform&) = delete;
  C2rTransform& operator=(const C2rTransform&) = delete;

  std::size_t spectrum_size() const { return static_cast<std::size_t>(n_z_) * (n_x_ / 2 + 1); }
  std::size_t grid_size() const { return static_cast<std::size_t>(n_z_) * n_x_; }

  // A fresh zeroed half-spectrum buffer with the planned alignment.
  FftwArray<fftwf_complex> make_spectrum() const;

  // Transforms `in` (an array from make_spectrum(); destroyed, as c2r does) into `out`. An `out`
  // aligned differently from the plan goes through an internal buffer and a copy.
  void execute(fftwf_complex* in, float* out);

 private:
  int n_x_;
  int n_z_;
  FftwArray<float> staging_;  // planned output; also the detour for misaligned outputs
  fftwf_plan plan_ = nullptr;
  int out_alignment_ = 0;
};

}  // namespace ocean::sim
