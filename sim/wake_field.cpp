// The forced, damped modes of the wake region, stepped exactly, and their synthesis.
#include "wake_field.hpp"

#include "c2r_transform.hpp"
#include "sea_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocean::sim {

WakeField::WakeField(const WakeRegion& region)
    : region_(region), columns_(region.n / 2 + 1), pressure_(region.n, region.size_m) {
  const int n = region.n;
  if (n < 16 || n > 4096 || (n & (n - 1)) != 0)
    throw ParamError(bad_param("wake n", n, "a power of two in [16, 4096]"));
  if (!(region.size_m > 0.0 && std::isfinite(region.size_m)))
    throw ParamError(bad_param("wake size_m", region.size_m, "a finite size > 0 metres"));
  if (!(region.decay_per_s >= 0.0 && region.viscosity_m2ps >= 0.0 && region.depth_m > 0.0 && region.gravity_mps2 > 0.0))
    throw ParamError("wake region: decay, viscosity >= 0 and depth, gravity > 0 required");
  kx_.resize(columns_);
  for (int i = 0; i < columns_; ++i) kx_[i] = wavenumber(i, region.size_m);
  kz_.resize(n);
  for (int j = 0; j < n; ++j) kz_[j] = wavenumber(j < n / 2 ? j : j - n, region.size_m);
  const std::size_t modes = static_cast<std::size_t>(n) * columns_;
  set_frequencies();
  eta_.assign(modes, {});
  velocity_.assign(modes, {});
  forcing_.assign(modes, {});
  synthesis_ = std::make_unique<C2rTransform>(n, n);
}

void WakeField::set_frequencies() {
  const int n = region_.n;
  const std::size_t modes = static_cast<std::size_t>(n) * columns_;
  omega_.resize(modes);
  gamma_.resize(modes);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < columns_; ++i) {
      const double k = std::hypot(kx_[i], kz_[j]);
      const std::size_t m = static_cast<std::size_t>(j) * columns_ + i;
      omega_[m] = angular_frequency(k, region_.gravity_mps2, region_.depth_m);
      gamma_[m] = region_.decay_per_s + 2.0 * region_.viscosity_m2ps * k * k;
    }
  step_dt_ = 0.0;  // the propagator follows at the next step
}

void WakeField::set_depth(double depth_m) {
  if (depth_m == region_.depth_m) return;
  if (!(depth_m > 0.0)) throw ParamError(bad_param("wake depth_m", depth_m, "> 0 (infinity: deep water)"));
  region_.depth_m = depth_m;
  set_frequencies();
}

WakeField::~WakeField() = default;
WakeField::WakeField(WakeField&&) noexcept = default;
WakeField& WakeField::operator=(WakeField&&) noexcept = default;

// The damped oscillator's exact propagator over dt for (xi, xi') with xi = eta + p / (rho g):
// xi(t + dt) = e^{-g dt} [(C + g S) xi + S xi'], xi'(t + dt) = e^{-g dt} [-w^2 S xi + (C - g S) xi'],
// with C = cos(wd dt), S = sin(wd dt) / wd, wd = sqrt(w^2 - g^2) for a wave; and for an overdamped
// mode (g > w: only with strong damping) C = cosh(r dt), S = sinh(r dt) / r, r = sqrt(g^2 - w^2).
void WakeField::prepare_step(double dt_s) {
  if (dt_s == step_dt_) return;
  step_dt_ = dt_s;
  const std::size_t modes = omega_.size();
  // The identity for modes that never move (skipped below): they start at 0 and (0 + p) - p is 0.
  c_ee_.assign(modes, 1.0);
  c_ev_.assign(modes, 0.0);
  c_ve_.assign(modes, 0.0);
  c_vv_.assign(modes, 1.0);
  const int n = region_.n;
  for (std::size_t m = 0; m < modes; ++m) {
    const double w = omega_[m], g = gamma_[m];
    // The mean level (k = 0) never moves: a wake moves no water on average. The Nyquist row and
    // column stay 0, so the field stays real.
    const auto row = static_cast<int>(m / columns_), column = static_cast<int>(m % columns_);
    if (w == 0.0 || row == n / 2 || column == n / 2) continue;
    double c, sd;  // e^{-g dt} C and e^{-g dt} S
    if (w > g) {
      const double wd = std::sqrt(w * w - g * g), e = std::exp(-g * dt_s);
      c = e * std::cos(wd * dt_s);
      sd = e * std::sin(wd * dt_s) / wd;
    } else {
      // As the two decays e^{-(g -+ r) dt}, so that no cosh overflows under strong damping;
      // g - r = w^2 / (g + r) without cancellation.
      const double r = std::sqrt(g * g - w * w);
      const double slow = std::exp(-w * w / (g + r) * dt_s), fast = std::exp(-(g + r) * dt_s);
      c = 0.5 * (slow + fast);
      sd = r * dt_s < 1e-8 ? std::exp(-g * dt_s) * dt_s : 0.5 * (slow - fast) / r;
    }
    c_ee_[m] = c + g * sd;
    c_ev_[m] = sd;
    c_ve_[m] = -w * w * sd;
    c_vv_[m] = c - g * sd;
  }
}

void WakeField::step(double dt_s, std::span<const HullPose> mid) {
  if (!(dt_s > 0.0 && dt_s <= 1.0)) throw ParamError(bad_param("wake dt", dt_s, "(0, 1] s"));
  prepare_step(dt_s);
  // Flat over real and imaginary parts (std::complex is laid out as two doubles), so the loops
  // vectorise; a mode that never moves has the identity propagator and stays exactly 0.
  double* eta = reinterpret_cast<double*>(eta_.data());
  double* velocity = reinterpret_cast<double*>(velocity_.data());
  const std::size_t modes = eta_.size();
  if (mid.empty()) {
    // Free ringing (an epoch's part after its epoch): no forcing to build or add.
    for (std::size_t m = 0; m < modes; ++m)
      for (std::size_t part = 2 * m; part < 2 * m + 2; ++part) {
        const double xi = eta[part], v = velocity[part];
        eta[part] = c_ee_[m] * xi + c_ev_[m] * v;
        velocity[part] = c_ve_[m] * xi + c_vv_[m] * v;
      }
  } else {
    std::fill(forcing_.begin(), forcing_.end(), std::complex<double>{});
    pressure_.add(mid, 1.0, forcing_.data());
    const double* p = reinterpret_cast<const double*>(forcing_.data());
    for (std::size_t m = 0; m < modes; ++m)
      for (std::size_t part = 2 * m; part < 2 * m + 2; ++part) {
        const double xi = eta[part] + p[part], v = velocity[part];
        eta[part] = c_ee_[m] * xi + c_ev_[m] * v - p[part];
        velocity[part] = c_ve_[m] * xi + c_vv_[m] * v;
      }
  }
  time_s_ += dt_s;
}

std::vector<double> WakeField::heights() const {
  const int n = region_.n;
  FftwArray<fftwf_complex> in = synthesis_->make_spectrum();
  for (std::size_t m = 0; m < eta_.size(); ++m) {
    in[m][0] = static_cast<float>(eta_[m].real());
    in[m][1] = static_cast<float>(eta_[m].imag());
  }
  // An output of the plan's own alignment: FFTW then runs it on these arrays, never on the plan's
  // staging buffer, so concurrent calls do not share memory.
  const FftwArray<float> out = fftw_array<float>(static_cast<std::size_t>(n) * n);
  synthesis_->execute(in.get(), out.get());
  return std::vector<double>(out.get(), out.get() + static_cast<std::size_t>(n) * n);
}

double WakeField::height_at(double x_m, double z_m) const {
  const int n = region_.n;
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < columns_; ++i) {
      const std::complex<double>& a = eta_[static_cast<std::size_t>(j) * columns_ + i];
      if (a == std::complex<double>{}) continue;
      // Columns 1 .. n/2 - 1 stand for their conjugate partners at -k too.
      const double weight = (i == 0 || i == n / 2) ? 1.0 : 2.0;
      const double phase = kx_[i] * x_m + kz_[j] * z_m;
      sum += weight * (a.real() * std::cos(phase) - a.imag() * std::sin(phase));
    }
  return sum;
}

}  // namespace ocean::sim
