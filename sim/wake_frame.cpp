#include "wake_frame.hpp"

#include "c2r_transform.hpp"
#include "sea_model.hpp"

#include <cmath>
#include <complex>

namespace ocean::sim {

struct WakeSampler::Plan {
  explicit Plan(int grid) : grid(grid), fft(grid, grid), spectrum(fft.make_spectrum()) {}
  // The wavenumbers of this grid's half spectrum over a region of side size_m (kept until it changes).
  void prepare(double region_m) {
    if (region_m == size_m) return;
    size_m = region_m;
    const int columns = grid / 2 + 1;
    kx.resize(columns);
    for (int i = 0; i < columns; ++i) kx[i] = wavenumber(i, size_m);
    kz.resize(grid);
    for (int j = 0; j < grid; ++j) kz[j] = wavenumber(j < grid / 2 ? j : j - grid, size_m);
    length_k.resize(static_cast<std::size_t>(grid) * columns);
    inverse_k.resize(length_k.size());
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < columns; ++i) {
        const double k = std::hypot(kx[i], kz[j]);
        length_k[static_cast<std::size_t>(j) * columns + i] = k;
        inverse_k[static_cast<std::size_t>(j) * columns + i] = k > 0.0 ? 1.0 / k : 0.0;
      }
  }
  int grid;
  C2rTransform fft;
  FftwArray<fftwf_complex> spectrum;
  std::vector<std::complex<double>> band;  // the wake's modes on this grid's half spectrum
  double size_m = 0.0;
  std::vector<double> kx, kz, length_k, inverse_k;
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

// One channel: each mode times `factor(kx, kz, k, 1/k)`, a real number, or i times it where
// `Imaginary` (a derivative), synthesized into `out`.
template <bool Imaginary, typename Factor>
void synthesize(WakeSampler::Plan& p, Factor factor, std::vector<float>& out) {
  const int grid = p.grid, columns = grid / 2 + 1;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < columns; ++i) {
      const std::size_t m = static_cast<std::size_t>(j) * columns + i;
      const double f = factor(p.kx[i], p.kz[j], p.length_k[m], p.inverse_k[m]);
      const std::complex<double> v = p.band[m];
      p.spectrum[m][0] = static_cast<float>(Imaginary ? -(v.imag() * f) : v.real() * f);
      p.spectrum[m][1] = static_cast<float>(Imaginary ? v.real() * f : v.imag() * f);
    }
  out.resize(static_cast<std::size_t>(grid) * grid);
  p.fft.execute(p.spectrum.get(), out.data());
}

// A channel's factor of the height spectrum (common/channels.hpp: -i G for disp, G for
// derivative), its products taken as they always were: the frames' bits depend on it.
double wake_factor(const ChannelInfo& c, double lambda, double kx, double kz, double k, double inv_k) {
  switch (c.kind) {
    case ChannelKind::height: return 1.0;
    case ChannelKind::slope_x: return kx;
    case ChannelKind::slope_z: return kz;
    case ChannelKind::disp: return -ocean::channel_factor(c.factor, lambda, kx, kz, k, inv_k);
    case ChannelKind::derivative: return ocean::channel_factor(c.factor, lambda, kx, kz, k, inv_k);
    case ChannelKind::none: break;
  }
  return 0.0;
}

// i times the factor: the odd derivatives (the slopes, the displacement).
bool imaginary(ChannelKind k) { return k == ChannelKind::slope_x || k == ChannelKind::slope_z || k == ChannelKind::disp; }

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
  p.prepare(size);
  out.n_x = out.n_z = grid;
  out.patch_x_m = out.patch_z_m = size;
  out.time_s = wake.time_s();
  const double lambda = choppiness;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const ChannelInfo& c = kChannels[ch];
    std::vector<float>& field = out.*kFrameChannels[static_cast<std::size_t>(ch)];
    field.clear();
    if (!requested(static_cast<std::size_t>(ch), request)) continue;
    const auto factor = [&](double kx, double kz, double k, double inv_k) {
      return wake_factor(c, lambda, kx, kz, k, inv_k);
    };
    if (imaginary(c.kind)) synthesize<true>(p, factor, field);
    else synthesize<false>(p, factor, field);
  }
  out.jacobian.clear();
  if (!request.choppy) return;
  out.jacobian.resize(out.height.size());
  for (std::size_t i = 0; i < out.jacobian.size(); ++i)
    out.jacobian[i] = (1.0f + out.disp_xx[i]) * (1.0f + out.disp_zz[i]) - out.disp_xz[i] * out.disp_xz[i];
}

}  // namespace ocean::sim
