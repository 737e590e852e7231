// FFTW plan lifetime and the planner's thread safety.
#include "c2r_transform.hpp"

#include <fftw3.h>

#include <cstring>
#include <mutex>
#include <new>

namespace ocean::sim {

// FFTW's planner (plan creation and destruction) is process-global and not thread-safe, while
// Oceans may be built on several threads (server, load test). fftwf_make_planner_thread_safe()
// (libfftw3f_threads) makes FFTW lock every planner call itself, which also protects any other FFTW
// user in the process -- a mutex of our own could only serialise our own calls. The once_flag is
// the only static here; it guards installing FFTW's own (global) hooks exactly once.
void make_fftw_planner_thread_safe() {
  static std::once_flag once;
  std::call_once(once, [] { fftwf_make_planner_thread_safe(); });
}

C2rTransform::C2rTransform(int n_x, int n_z) : n_x_(n_x), n_z_(n_z), staging_(fftw_array<float>(grid_size())) {
  make_fftw_planner_thread_safe();
  FftwArray<fftwf_complex> in = make_spectrum();
  if (!in || !staging_) throw std::bad_alloc();
  // FFTW_ESTIMATE: the plan comes from FFTW's cost model alone, not from timing, so two processes
  // (and two runs) execute the same codelets and produce bit-identical frames; FFTW_MEASURE was only
  // 12-18% faster on c2r here (256^2, 512^2) and may pick differently per process. SIMD codelets
  // stay on: FFTW chooses them from the CPU and the buffers' alignment (fixed by fftwf_malloc) only,
  // and FFTW_NO_SIMD doubled the c2r time (0.83 -> 1.93 ms at 512^2).
  plan_ = fftwf_plan_dft_c2r_2d(n_z_, n_x_, in.get(), staging_.get(), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  if (!plan_) throw std::bad_alloc();
  out_alignment_ = fftwf_alignment_of(staging_.get());
}

C2rTransform::~C2rTransform() {
  if (plan_) fftwf_destroy_plan(plan_);
}

FftwArray<fftwf_complex> C2rTransform::make_spectrum() const {
  FftwArray<fftwf_complex> a = fftw_array<fftwf_complex>(spectrum_size());
  if (!a) throw std::bad_alloc();
  std::memset(a.get(), 0, sizeof(fftwf_complex) * spectrum_size());
  return a;
}

void C2rTransform::execute(fftwf_complex* in, float* out) {
  if (fftwf_alignment_of(out) == out_alignment_) {
    fftwf_execute_dft_c2r(plan_, in, out);
    return;
  }
  fftwf_execute_dft_c2r(plan_, in, staging_.get());
  std::memcpy(out, staging_.get(), sizeof(float) * grid_size());
}

}  // namespace ocean::sim
