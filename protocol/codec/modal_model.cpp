// Coefficient tables, the two-step recurrence, synthesis of heights/slopes, correction folding.
#include "modal_model.hpp"

#include "det_math.hpp"
#include "fixed_point.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace ocean::codec {
namespace {

// Signed wavenumber index of FFT bin i on an n grid; the Nyquist bin is -n/2.
int signed_index(int i, int n) { return i < n / 2 ? i : i - n; }

const StreamConfig& require_valid(const StreamConfig& config) {
  const std::string err = validate(config);
  if (!err.empty()) throw std::invalid_argument("stream config: " + err);
  return config;
}

}  // namespace

ModalModel::ModalModel(const StreamConfig& config)
    : n_(require_valid(config).grid), log2n_(config.grid_log2()), normals_(config.normals), fft_(config.grid) {
  const int n = n_, hc = n / 2 + 1;
  const double dt = config.dt_s();  // one tick step: deltas advance (tick - baseline) steps
  a_.resize(static_cast<std::size_t>(n) * hc);
  for (int r = 0; r < n; ++r) {
    const double kz = kTwoPi * signed_index(r, n) / config.patch_z_m;
    for (int c = 0; c < hc; ++c) {
      const double kx = kTwoPi * signed_index(c, n) / config.patch_x_m;
      const double k = std::sqrt(kx * kx + kz * kz);
      const double w = det_angular_frequency(k, config.gravity_mps2, config.depth_m);
      a_[r * hc + c] = to_fixed(2.0 * det_cos(w * dt), kRecurrenceBits);
    }
  }
  // d/dx in spectral space is i kx; the factor converts height units per metre to slope units.
  const double factor = (static_cast<double>(config.height_step_m) / 65536.0) /
                        (static_cast<double>(config.slope_step) / 4096.0);
  kx_coef_.assign(hc, 0);
  kz_coef_.assign(n, 0);
  if (normals_) {
    for (int c = 0; c < n / 2; ++c) kx_coef_[c] = to_fixed(kTwoPi * c / config.patch_x_m * factor, kSlopeCoefBits);
    for (int r = 0; r < n; ++r)
      if (r != n / 2) kz_coef_[r] = to_fixed(kTwoPi * signed_index(r, n) / config.patch_z_m * factor, kSlopeCoefBits);
  }
  for (int r = 0; r < n; ++r) {
    if (r == n / 2) continue;
    for (int c = 0; c < n / 2; ++c) {
      if (c == 0 && !(r >= 1 && r < n / 2)) continue;
      key_modes_.push_back(r * hc + c);
    }
  }
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  z_re_.resize(nn);
  z_im_.resize(nn);
  w_re_.resize(nn);
  w_im_.resize(nn);
}

ModalState ModalModel::zero_state() const {
  ModalState s;
  const std::size_t m = static_cast<std::size_t>(half_size());
  s.prev.re.assign(m, 0);
  s.prev.im.assign(m, 0);
  s.cur = s.prev;
  return s;
}

void ModalModel::advance(ModalState& s) const {
  const std::size_t m = a_.size();
  for (std::size_t i = 0; i < m; ++i) {
    s.prev.re[i] = wsub(mul_round_sym(a_[i], s.cur.re[i], kRecurrenceBits), s.prev.re[i]);
    s.prev.im[i] = wsub(mul_round_sym(a_[i], s.cur.im[i], kRecurrenceBits), s.prev.im[i]);
  }
  std::swap(s.prev, s.cur);
}

void ModalModel::advance(ModalState& s, std::uint64_t steps) const {
  for (std::uint64_t i = 0; i < steps; ++i) advance(s);
}

void ModalModel::synthesize(const HalfSpectrum& cur, SampleFields& out) {
  const int n = n_, hc = n / 2 + 1, shift = 2 * log2n_;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  for (int r = 0; r < n; ++r) {
    const int rm = (n - r) % n;
    for (int c = 0; c < hc; ++c) {
      const std::int64_t hr = cur.re[r * hc + c], hi = cur.im[r * hc + c];
      // Z = H + i Sx with Sx = i kx H, so one inverse FFT gives height (real) and slope_x (imag).
      std::int64_t sxr = 0, sxi = 0, szr = 0, szi = 0;
      if (normals_) {
        sxr = -mul_round_sym(kx_coef_[c], hi, kSlopeCoefBits);
        sxi = mul_round_sym(kx_coef_[c], hr, kSlopeCoefBits);
        szr = -mul_round_sym(kz_coef_[r], hi, kSlopeCoefBits);
        szi = mul_round_sym(kz_coef_[r], hr, kSlopeCoefBits);
      }
      const std::size_t at = static_cast<std::size_t>(r) * n + c;
      z_re_[at] = wsub(hr, sxi);
      z_im_[at] = wadd(hi, sxr);
      w_re_[at] = szr;
      w_im_[at] = szi;
      if (c > 0 && c < n / 2) {  // the conjugate partner -k
        const std::size_t mat = static_cast<std::size_t>(rm) * n + (n - c);
        z_re_[mat] = wadd(hr, sxi);
        z_im_[mat] = wsub(sxr, hi);
        w_re_[mat] = szr;
        w_im_[mat] = -szi;
      }
    }
  }
  fft_.inverse_2d(z_re_.data(), z_im_.data());
  out.height.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) out.height[i] = round_shift64(z_re_[i], shift);
  if (!normals_) {
    out.slope_x.clear();
    out.slope_z.clear();
    return;
  }
  out.slope_x.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) out.slope_x[i] = round_shift64(z_im_[i], shift);
  fft_.inverse_2d(w_re_.data(), w_im_.data());
  out.slope_z.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) out.slope_z[i] = round_shift64(w_re_[i], shift);
}

void ModalModel::spectrum_of(const std::int64_t* field, HalfSpectrum& out) {
  const int n = n_, hc = n / 2 + 1;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  for (std::size_t i = 0; i < nn; ++i) {
    z_re_[i] = field[i];
    z_im_[i] = 0;
  }
  fft_.forward_2d(z_re_.data(), z_im_.data());
  out.re.resize(static_cast<std::size_t>(half_size()));
  out.im.resize(out.re.size());
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < hc; ++c) {
      out.re[r * hc + c] = z_re_[static_cast<std::size_t>(r) * n + c];
      out.im[r * hc + c] = z_im_[static_cast<std::size_t>(r) * n + c];
    }
  // Columns kx = 0 and kx = n/2 hold both k and -k: take the rows up to n/2 as the truth.
  for (int c : {0, n / 2}) {
    for (int r = n / 2 + 1; r < n; ++r) {
      out.re[r * hc + c] = out.re[(n - r) * hc + c];
      out.im[r * hc + c] = -out.im[(n - r) * hc + c];
    }
    out.im[c] = 0;
    out.im[(n / 2) * hc + c] = 0;
  }
}

void ModalModel::add_correction(ModalState& s, const std::vector<std::int64_t>& field) {
  HalfSpectrum d;
  spectrum_of(field.data(), d);
  for (std::size_t i = 0; i < d.re.size(); ++i) {
    s.cur.re[i] = wadd(s.cur.re[i], d.re[i]);
    s.cur.im[i] = wadd(s.cur.im[i], d.im[i]);
    s.prev.re[i] = wadd(s.prev.re[i], d.re[i]);
    s.prev.im[i] = wadd(s.prev.im[i], d.im[i]);
  }
}

void ModalModel::mirror_key_column(HalfSpectrum& s) const {
  const int n = n_, hc = n / 2 + 1;
  for (int r = n / 2 + 1; r < n; ++r) {
    s.re[r * hc] = s.re[(n - r) * hc];
    s.im[r * hc] = -s.im[(n - r) * hc];
  }
}

}  // namespace ocean::codec
