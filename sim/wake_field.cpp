// The forced, damped modes of the wake region, stepped exactly, and their synthesis.
#include "wake_field.hpp"

#include "sea_model.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ocean::sim {
namespace {

// Beyond this exponent a hull's pressure spectrum is below e^-40 of its peak: the mode is not forced.
constexpr double kNegligibleExponent = 40.0;

// In-place radix-2 DFT of n points `stride` apart, X[j] = sum x[i] e^{+2 pi i i j / n} (synthesis);
// twiddle[m] = e^{+2 pi i m / n}, m < n / 2.
void inverse_dft(std::complex<double>* x, int n, std::size_t stride, const std::vector<std::complex<double>>& twiddle) {
  for (int i = 1, j = 0; i < n; ++i) {
    int bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i * stride], x[j * stride]);
  }
  for (int len = 2; len <= n; len <<= 1) {
    const int step = n / len;
    for (int start = 0; start < n; start += len)
      for (int k = 0; k < len / 2; ++k) {
        std::complex<double>& a = x[(start + k) * stride];
        std::complex<double>& b = x[(start + k + len / 2) * stride];
        const std::complex<double> t = b * twiddle[static_cast<std::size_t>(k * step)];
        b = a - t;
        a += t;
      }
  }
}

}  // namespace

WakeField::WakeField(const WakeRegion& region) : region_(region) {
  const int n = region.n;
  if (n < 16 || n > 4096 || (n & (n - 1)) != 0)
    throw ParamError(bad_param("wake n", n, "a power of two in [16, 4096]"));
  if (!(region.size_m > 0.0 && std::isfinite(region.size_m)))
    throw ParamError(bad_param("wake size_m", region.size_m, "a finite size > 0 metres"));
  if (!(region.decay_per_s >= 0.0 && region.viscosity_m2ps >= 0.0 && region.depth_m > 0.0 && region.gravity_mps2 > 0.0))
    throw ParamError("wake region: decay, viscosity >= 0 and depth, gravity > 0 required");
  kx_.resize(n);
  for (int i = 0; i < n; ++i) kx_[i] = wavenumber(i < n / 2 ? i : i - n, region.size_m);
  kz_ = kx_;
  const std::size_t modes = static_cast<std::size_t>(n) * n;
  omega_.resize(modes);
  gamma_.resize(modes);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double k = std::hypot(kx_[i], kz_[j]);
      const std::size_t m = static_cast<std::size_t>(j) * n + i;
      omega_[m] = angular_frequency(k, region.gravity_mps2, region.depth_m);
      gamma_[m] = region.decay_per_s + 2.0 * region.viscosity_m2ps * k * k;
    }
  eta_.assign(modes, {});
  velocity_.assign(modes, {});
  pressure_.assign(modes, {});
}

// The damped oscillator's exact propagator over dt for (xi, xi') with xi = eta + p / (rho g):
// xi(t + dt) = e^{-g dt} [(cos + g sin / wd) xi + (sin / wd) xi'],
// xi'(t + dt) = e^{-g dt} [-(w^2 sin / wd) xi + (cos - g sin / wd) xi'], wd = sqrt(w^2 - g^2).
void WakeField::prepare_step(double dt_s) {
  if (dt_s == step_dt_) return;
  step_dt_ = dt_s;
  const std::size_t modes = omega_.size();
  c_ee_.assign(modes, 0.0);
  c_ev_.assign(modes, 0.0);
  c_ve_.assign(modes, 0.0);
  c_vv_.assign(modes, 0.0);
  for (std::size_t m = 0; m < modes; ++m) {
    const double w = omega_[m], g = gamma_[m];
    if (w <= g) continue;  // the mean level (k = 0): a wake moves no water on average
    const double wd = std::sqrt(w * w - g * g);
    const double e = std::exp(-g * dt_s), c = std::cos(wd * dt_s), s = std::sin(wd * dt_s);
    c_ee_[m] = e * (c + g * s / wd);
    c_ev_[m] = e * s / wd;
    c_ve_[m] = -e * w * w * s / wd;
    c_vv_[m] = e * (c - g * s / wd);
  }
}

// p / (rho g) of a Gaussian hull, as Fourier coefficients over the region: draft 2 pi sx sz / A
// exp(-(k_along^2 sx^2 + k_across^2 sz^2) / 2) e^{-i k.x}.
void WakeField::add_pressure(const HullPose& pose, std::vector<std::complex<double>>& pressure) const {
  const int n = region_.n;
  const double sx = 0.25 * pose.hull.length_m, sz = 0.25 * pose.hull.beam_m;
  const double peak = pose.hull.draft_m * 2.0 * std::numbers::pi * sx * sz / (region_.size_m * region_.size_m);
  const double c = std::cos(pose.heading_rad), s = std::sin(pose.heading_rad);
  // e^{-i k.x} = e^{-i kx x} e^{-i kz z}: 2n phases, not n^2.
  std::vector<std::complex<double>> along_x(n), along_z(n);
  for (int i = 0; i < n; ++i) {
    along_x[i] = std::polar(1.0, -kx_[i] * pose.x_m);
    along_z[i] = std::polar(1.0, -kz_[i] * pose.z_m);
  }
  for (int j = 0; j < n; ++j) {
    if (j == n / 2) continue;  // Nyquist row and column stay 0: the field stays real
    for (int i = 0; i < n; ++i) {
      if (i == n / 2 || (i == 0 && j == 0)) continue;  // nor the mean level
      const double kx = kx_[i], kz = kz_[j];
      const double along = kx * c + kz * s, across = -kx * s + kz * c;
      const double exponent = 0.5 * (along * along * sx * sx + across * across * sz * sz);
      if (exponent > kNegligibleExponent) continue;
      pressure[static_cast<std::size_t>(j) * n + i] += peak * std::exp(-exponent) * (along_x[i] * along_z[j]);
    }
  }
}

void WakeField::step(double dt_s, std::span<const HullPose> mid) {
  if (!(dt_s > 0.0 && dt_s <= 1.0)) throw ParamError(bad_param("wake dt", dt_s, "(0, 1] s"));
  prepare_step(dt_s);
  std::fill(pressure_.begin(), pressure_.end(), std::complex<double>{});
  for (const HullPose& pose : mid) add_pressure(pose, pressure_);
  for (std::size_t m = 0; m < eta_.size(); ++m) {
    const std::complex<double> xi = eta_[m] + pressure_[m], v = velocity_[m];
    eta_[m] = c_ee_[m] * xi + c_ev_[m] * v - pressure_[m];
    velocity_[m] = c_ve_[m] * xi + c_vv_[m] * v;
  }
  time_s_ += dt_s;
}

std::vector<double> WakeField::heights() const {
  const int n = region_.n;
  std::vector<std::complex<double>> twiddle(static_cast<std::size_t>(n / 2));
  for (int m = 0; m < n / 2; ++m) twiddle[m] = std::polar(1.0, 2.0 * std::numbers::pi * m / n);
  std::vector<std::complex<double>> field = eta_;
  for (int j = 0; j < n; ++j) inverse_dft(field.data() + static_cast<std::size_t>(j) * n, n, 1, twiddle);
  for (int i = 0; i < n; ++i) inverse_dft(field.data() + i, n, static_cast<std::size_t>(n), twiddle);
  std::vector<double> out(field.size());
  for (std::size_t m = 0; m < field.size(); ++m) out[m] = field[m].real();
  return out;
}

double WakeField::height_at(double x_m, double z_m) const {
  const int n = region_.n;
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::complex<double>& a = eta_[static_cast<std::size_t>(j) * n + i];
      if (a == std::complex<double>{}) continue;
      const double phase = kx_[i] * x_m + kz_[j] * z_m;
      sum += a.real() * std::cos(phase) - a.imag() * std::sin(phase);
    }
  return sum;
}

}  // namespace ocean::sim
