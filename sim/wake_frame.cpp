#include "wake_frame.hpp"

#include "c2r_transform.hpp"
#include "sea_model.hpp"

#include <cmath>
#include <complex>

namespace ocean::sim {

struct WakeSampler::Plan {
  explicit Plan(int grid) : fft(grid, grid), spectrum(fft.make_spectrum()) {}
  C2rTransform fft;
  FftwArray<fftwf_complex> spectrum;
  std::vector<std::complex<double>> band;  // the wake's modes on this grid's half spectrum
};

WakeSampler::WakeSampler() = default;
WakeSampler::~WakeSampler() = default;
WakeSampler::WakeSampler(WakeSampler&&) noexcept = default;
WakeSampler& WakeSampler::operator=(WakeSampler&&) noexcept = default;

WakeSampler::Plan& WakeSampler::plan(int grid) {
  std::unique_ptr<Plan>& p = plans_[grid];
  if (!p) p = std::make_unique<Plan>(grid);
  return *p;
}

namespace {

// One channel: `factor(kx, kz)` times each mode (as a complex multiplier), synthesized into `out`.
template <typename Factor>
void synthesize(C2rTransform& fft, fftwf_complex* spectrum,
                const std::vector<std::complex<double>>& band, int grid, double size_m, Factor factor,
                std::vector<float>& out) {
  const int columns = grid / 2 + 1;
  for (int j = 0; j < grid; ++j) {
    const double kz = wavenumber(j < grid / 2 ? j : j - grid, size_m);
    for (int i = 0; i < columns; ++i) {
      const std::size_t m = static_cast<std::size_t>(j) * columns + i;
      const std::complex<double> v = band[m] * factor(wavenumber(i, size_m), kz);
      spectrum[m][0] = static_cast<float>(v.real());
      spectrum[m][1] = static_cast<float>(v.imag());
    }
  }
  out.resize(static_cast<std::size_t>(grid) * grid);
  fft.execute(spectrum, out.data());
}

}  // namespace

void WakeSampler::sample(const WakeField& wake, int grid, FrameRequest request, double choppiness, Frame& out) {
  const WakeField* one = &wake;
  sample(std::span<const WakeField* const>(&one, 1), grid, request, choppiness, out);
}

void WakeSampler::sample(std::span<const WakeField* const> wakes, int grid, FrameRequest request, double choppiness,
                         Frame& out) {
  const WakeField& wake = *wakes.front();
  const int n = wake.region().n;
  if (grid < 2 || grid > n || (grid & (grid - 1)) != 0)
    throw ParamError(bad_param("wake sample grid", grid, "a power of two up to the wake's " + std::to_string(n)));
  Plan& p = plan(grid);
  const int columns = grid / 2 + 1, wake_columns = n / 2 + 1;
  // Waves strictly below this grid's Nyquist: the lattice then holds the field exactly.
  p.band.assign(static_cast<std::size_t>(grid) * columns, {});
  for (int j = 0; j < grid; ++j) {
    const int signed_j = j < grid / 2 ? j : j - grid;
    if (signed_j == -grid / 2) continue;
    const int wake_row = signed_j >= 0 ? signed_j : signed_j + n;
    for (int i = 0; i < grid / 2; ++i)
      for (const WakeField* w : wakes)
        p.band[static_cast<std::size_t>(j) * columns + i] += w->modes()[static_cast<std::size_t>(wake_row) * wake_columns + i];
  }
  const double size = wake.region().size_m;
  out.n_x = out.n_z = grid;
  out.patch_x_m = out.patch_z_m = size;
  out.time_s = wake.time_s();
  using C = std::complex<double>;
  const auto channel = [&](auto factor, std::vector<float>& into) {
    synthesize(p.fft, p.spectrum.get(), p.band, grid, size, factor, into);
  };
  channel([](double, double) { return C(1.0); }, out.height);
  out.slope_x.clear();
  out.slope_z.clear();
  if (request.slopes) {
    channel([](double kx, double) { return C(0.0, kx); }, out.slope_x);
    channel([](double, double kz) { return C(0.0, kz); }, out.slope_z);
  }
  for (auto* v : {&out.disp_x, &out.disp_z, &out.disp_xx, &out.disp_zz, &out.disp_xz, &out.jacobian}) v->clear();
  if (!request.choppy) return;
  const double lambda = choppiness;
  const auto over_k = [](double kx, double kz) {
    const double k = std::hypot(kx, kz);
    return k > 0.0 ? 1.0 / k : 0.0;
  };
  channel([&](double kx, double kz) { return C(0.0, -lambda * kx * over_k(kx, kz)); }, out.disp_x);
  channel([&](double kx, double kz) { return C(0.0, -lambda * kz * over_k(kx, kz)); }, out.disp_z);
  channel([&](double kx, double kz) { return C(lambda * kx * kx * over_k(kx, kz)); }, out.disp_xx);
  channel([&](double kx, double kz) { return C(lambda * kz * kz * over_k(kx, kz)); }, out.disp_zz);
  channel([&](double kx, double kz) { return C(lambda * kx * kz * over_k(kx, kz)); }, out.disp_xz);
  out.jacobian.resize(out.height.size());
  for (std::size_t i = 0; i < out.jacobian.size(); ++i)
    out.jacobian[i] = (1.0f + out.disp_xx[i]) * (1.0f + out.disp_zz[i]) - out.disp_xz[i] * out.disp_xz[i];
}

}  // namespace ocean::sim
