#include "r2c_transform.hpp"

#include <cstring>
#include <new>

namespace ocean::sim {

R2cTransform::R2cTransform(int n_x, int n_z)
    : n_x_(n_x),
      n_z_(n_z),
      input_(fftw_array<float>(static_cast<std::size_t>(n_x) * n_z)),
      output_(fftw_array<fftwf_complex>(static_cast<std::size_t>(n_z) * (n_x / 2 + 1))) {
  make_fftw_planner_thread_safe();
  if (!input_ || !output_) throw std::bad_alloc();
  // The caller lays out a new input for every transform, so FFTW may use the input as scratch.
  plan_ = fftwf_plan_dft_r2c_2d(n_z_, n_x_, input_.get(), output_.get(), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  if (!plan_) throw std::bad_alloc();
  std::memset(input_.get(), 0, sizeof(float) * static_cast<std::size_t>(n_x) * n_z);
}

R2cTransform::~R2cTransform() {
  if (plan_) fftwf_destroy_plan(plan_);
}

void R2cTransform::execute() { fftwf_execute(plan_); }

}  // namespace ocean::sim
