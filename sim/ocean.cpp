// Ocean: parameter checks, the band evaluators (built on first use, the full grid at construction)
// and the double-precision reference h(k, t) of single modes.
#include "ocean.hpp"

#include "band_evaluator.hpp"
#include "sea_model.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace ocean::sim {
namespace {

constexpr double max_abs_time_s = 1e9;  // 31 years of server uptime

SceneParams checked(const SceneParams& params) {
  std::string error = validate(params);
  if (!error.empty()) throw ParamError(error);
  return params;
}

}  // namespace

struct Ocean::Impl {
  explicit Impl(const SceneParams& p) : params(checked(p)), spectrum(params) {
    const double kx_max = wavenumber(params.size_x / 2, params.patch_x_m);
    const double kz_max = wavenumber(params.size_z / 2, params.patch_z_m);
    omega_max = angular_frequency(std::hypot(kx_max, kz_max), params.gravity_mps2, params.depth_m);
    // phase_sincos() needs |w t| (2/pi) < 2^50; keep a wide margin.
    time_limit_s = std::min(max_abs_time_s, 0x1.0p46 / omega_max);
    band(params.size_x, params.size_z);
  }

  BandEvaluator& band(int n_x, int n_z) {
    for (auto& b : bands)
      if (b->n_x() == n_x && b->n_z() == n_z) return *b;
    bands.push_back(std::make_unique<BandEvaluator>(build_mode_table(params, spectrum, n_x, n_z), params.choppiness,
                                                    params.patch_x_m, params.patch_z_m));
    return *bands.back();
  }

  BandEvaluator& checked_band(int n_x, int n_z) {
    if (!power_of_two_in(n_x, 16, params.size_x))
      throw ParamError(bad_param("band n_x", n_x, "a power of two in [16, size_x = " + std::to_string(params.size_x) + "]"));
    if (!power_of_two_in(n_z, 16, params.size_z))
      throw ParamError(bad_param("band n_z", n_z, "a power of two in [16, size_z = " + std::to_string(params.size_z) + "]"));
    return band(n_x, n_z);
  }

  void check_time(double t) const {
    if (!(std::fabs(t) <= time_limit_s))
      throw ParamError(bad_param("t", t, "finite with |t| <= " + format_value(time_limit_s) + " s"));
  }

  SceneParams params;
  Spectrum spectrum;
  double omega_max = 0.0;
  double time_limit_s = 0.0;
  std::vector<std::unique_ptr<BandEvaluator>> bands;  // bands[0] is the full grid
};

Ocean::Ocean(const SceneParams& params) : impl_(std::make_unique<Impl>(params)) {}
Ocean::~Ocean() = default;
Ocean::Ocean(Ocean&&) noexcept = default;
Ocean& Ocean::operator=(Ocean&&) noexcept = default;

const SceneParams& Ocean::params() const { return impl_->params; }

void Ocean::evaluate(double t, Frame& out, FrameRequest request) {
  impl_->check_time(t);
  impl_->bands.front()->evaluate(t, out, request);
}

void Ocean::evaluate_band(double t, int n_x, int n_z, Frame& out, FrameRequest request) {
  impl_->check_time(t);
  impl_->checked_band(n_x, n_z).evaluate(t, out, request);
}

void Ocean::prepare_band(int n_x, int n_z) { impl_->checked_band(n_x, n_z); }

std::complex<double> Ocean::mode_amplitude(double t, int kx, int kz) const {
  const SceneParams& p = impl_->params;
  if (std::abs(kx) >= p.size_x / 2 || std::abs(kz) >= p.size_z / 2) return {};
  const std::complex<double> a = initial_amplitude(p, impl_->spectrum, kx, kz);
  const std::complex<double> b = std::conj(initial_amplitude(p, impl_->spectrum, -kx, -kz));
  const double k = std::hypot(wavenumber(kx, p.patch_x_m), wavenumber(kz, p.patch_z_m));
  const double phase = std::fmod(angular_frequency(k, p.gravity_mps2, p.depth_m) * t, 2.0 * std::numbers::pi);
  return a * std::polar(1.0, -phase) + b * std::polar(1.0, phase);
}

double Ocean::expected_variance() const {
  const SceneParams& p = impl_->params;
  const double dk2 = wavenumber(1, p.patch_x_m) * wavenumber(1, p.patch_z_m);
  double sum = 0.0;
  for (int kz = -p.size_z / 2 + 1; kz < p.size_z / 2; ++kz)
    for (int kx = -p.size_x / 2 + 1; kx < p.size_x / 2; ++kx)
      if (p.band.keeps(kx, kz)) sum += impl_->spectrum.density(wavenumber(kx, p.patch_x_m), wavenumber(kz, p.patch_z_m));
  return sum * dk2;
}

int Ocean::transform_count(FrameRequest request) const { return BandEvaluator::transform_count(request); }

void Ocean::execute_transforms_only(Frame& frame, FrameRequest request) {
  impl_->bands.front()->execute_transforms_only(frame, request);
}

}  // namespace ocean::sim
