#include "r2c_transform.hpp"

#include <cstring>
#include <new>

namespace ocean::sim {

R2cTransform::R2cTransform(int n_x, int n_z)
    : n_x_(n_x),
      n_z_(n_z),
      input_(fftw_array<float>(static_cast<std::size_t>(n_x) * n_z)),
      output_(fftw_array<fftwf_complex>(static_cast<std::size_t>(n_z) * (n_x / 2 + 1))),
      scratch_(fftw_array<float>(static_cast<std::size_t>(n_x) * n_z)) {
  make_fftw_planner_thread_safe();
  if (!input_ || !output_ || !scratch_) throw std::bad_alloc();
  plan_ = fftwf_plan_dft_r2c_2d(n_z_, n_x_, scratch_.get(), output_.get(), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  if (!plan_) throw std::bad_alloc();
  std::memset(input_.get(), 0, sizeof(float) * static_cast<std::size_t>(n_x) * n_z);
}

R2cTransform::~R2cTransform() {
  if (plan_) fftwf_destroy_plan(plan_);
}

void R2cTransform::execute() {
  std::memcpy(scratch_.get(), input_.get(), sizeof(float) * static_cast<std::size_t>(n_x_) * n_z_);
  fftwf_execute(plan_);
}

}  // namespace ocean::sim
