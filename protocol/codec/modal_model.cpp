// Coefficient tables, the two-step recurrence, synthesis of heights, slopes and choppy channels,
// correction folding.
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
    : n_(require_valid(config).grid),
      log2n_(config.grid_log2()),
      normals_(config.normals),
      choppy_(config.choppy),
      patch_x_m_(config.patch_x_m),
      patch_z_m_(config.patch_z_m),
      fft_(config.grid) {
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
  disp_factor_ = (static_cast<double>(config.height_step_m) / 65536.0) / (static_cast<double>(config.disp_step_m) / 65536.0);
  jac_factor_ = factor;
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

void ModalModel::build_choppy_coefficients(double choppiness) {
  const int n = n_, hc = n / 2 + 1;
  const std::size_t m = static_cast<std::size_t>(n) * hc;
  if (ratio_[0].empty()) {
    for (auto& r : ratio_) r.assign(m, 0.0);
    for (int r = 0; r < n; ++r) {
      if (r == n / 2) continue;
      const double kz = kTwoPi * signed_index(r, n) / patch_z_m_;
      for (int c = 0; c < n / 2; ++c) {
        const double kx = kTwoPi * c / patch_x_m_;
        const double k = std::sqrt(kx * kx + kz * kz);
        if (k == 0.0) continue;
        const std::size_t at = static_cast<std::size_t>(r) * hc + c;
        ratio_[0][at] = kx / k;
        ratio_[1][at] = kz / k;
        ratio_[2][at] = (kx * kx) / k;
        ratio_[3][at] = (kz * kz) / k;
        ratio_[4][at] = (kx * kz) / k;
      }
    }
  }
  for (int j = 0; j < 5; ++j) {
    const double factor = j < 2 ? disp_factor_ : jac_factor_;
    choppy_coef_[j].resize(m);
    for (std::size_t i = 0; i < m; ++i) choppy_coef_[j][i] = to_fixed(choppiness * ratio_[j][i] * factor, kChoppyCoefBits);
  }
  coef_choppiness_ = choppiness;
}

void ModalModel::synthesize_pair(const std::int64_t* ar, const std::int64_t* ai, const std::int64_t* br,
                                 const std::int64_t* bi, std::vector<std::int64_t>& a, std::vector<std::int64_t>* b) {
  const int n = n_, hc = n / 2 + 1, shift = 2 * log2n_;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  for (int r = 0; r < n; ++r) {
    const int rm = (n - r) % n;
    for (int c = 0; c < hc; ++c) {
      const std::size_t h = static_cast<std::size_t>(r) * hc + c;
      // Z = A + iB: one inverse FFT gives A (real part) and B (imaginary part).
      const std::int64_t xr = ar[h], xi = ai[h], yr = br ? br[h] : 0, yi = bi ? bi[h] : 0;
      const std::size_t at = static_cast<std::size_t>(r) * n + c;
      z_re_[at] = wsub(xr, yi);
      z_im_[at] = wadd(xi, yr);
      if (c > 0 && c < n / 2) {  // the conjugate partner -k
        const std::size_t mat = static_cast<std::size_t>(rm) * n + (n - c);
        z_re_[mat] = wadd(xr, yi);
        z_im_[mat] = wsub(yr, xi);
      }
    }
  }
  fft_.inverse_2d(z_re_.data(), z_im_.data());
  a.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) a[i] = round_shift64(z_re_[i], shift);
  if (!b) return;
  b->resize(nn);
  for (std::size_t i = 0; i < nn; ++i) (*b)[i] = round_shift64(z_im_[i], shift);
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out) {
  const int n = n_, hc = n / 2 + 1;
  const std::size_t m = static_cast<std::size_t>(half_size());
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  // The channels in order - height, [slope_x, slope_z], [disp_x, disp_z, disp_xx, disp_zz,
  // disp_xz] - as half-spectra, synthesized in consecutive pairs (CODEC.md 7.2).
  struct Channel {
    const std::int64_t *re, *im;
    std::vector<std::int64_t>* out;
  };
  Channel channels[8];
  int count = 0;
  channels[count++] = {cur.re.data(), cur.im.data(), &out.height};
  if (normals_) {
    for (int j = 0; j < 4; ++j) spec_[j].resize(m);
    std::int64_t *sxr = spec_[0].data(), *sxi = spec_[1].data(), *szr = spec_[2].data(), *szi = spec_[3].data();
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < hc; ++c) {
        const std::size_t h = static_cast<std::size_t>(r) * hc + c;
        const std::int64_t hr = cur.re[h], hi = cur.im[h];
        sxr[h] = -mul_round_sym(kx_coef_[c], hi, kSlopeCoefBits);  // i kx H
        sxi[h] = mul_round_sym(kx_coef_[c], hr, kSlopeCoefBits);
        szr[h] = -mul_round_sym(kz_coef_[r], hi, kSlopeCoefBits);
        szi[h] = mul_round_sym(kz_coef_[r], hr, kSlopeCoefBits);
      }
    channels[count++] = {sxr, sxi, &out.slope_x};
    channels[count++] = {szr, szi, &out.slope_z};
  } else {
    out.slope_x.clear();
    out.slope_z.clear();
  }
  std::vector<std::int64_t>* choppy_out[5] = {&out.disp_x, &out.disp_z, &out.disp_xx, &out.disp_zz, &out.disp_xz};
  if (choppy_ && choppiness == 0.0) {
    // Every factor is 0, so every field is exactly 0: no transforms needed.
    for (auto* f : choppy_out) f->assign(nn, 0);
  } else if (choppy_) {
    if (choppiness != coef_choppiness_) build_choppy_coefficients(choppiness);
    for (int j = 0; j < 5; ++j) {
      spec_[4 + 2 * j].resize(m);
      spec_[5 + 2 * j].resize(m);
      std::int64_t* re = spec_[4 + 2 * j].data();
      std::int64_t* im = spec_[5 + 2 * j].data();
      const std::int64_t* g = choppy_coef_[j].data();
      for (std::size_t h = 0; h < m; ++h) {
        const std::int64_t hr = cur.re[h], hi = cur.im[h];
        if (j < 2) {  // displacement: -i G H
          re[h] = mul_round_sym(g[h], hi, kChoppyCoefBits);
          im[h] = -mul_round_sym(g[h], hr, kChoppyCoefBits);
        } else {  // its derivatives: G H
          re[h] = mul_round_sym(g[h], hr, kChoppyCoefBits);
          im[h] = mul_round_sym(g[h], hi, kChoppyCoefBits);
        }
      }
      channels[count++] = {re, im, choppy_out[j]};
    }
  } else {
    for (auto* f : choppy_out) f->clear();
  }
  for (int i = 0; i < count; i += 2)
    synthesize_pair(channels[i].re, channels[i].im, i + 1 < count ? channels[i + 1].re : nullptr,
                    i + 1 < count ? channels[i + 1].im : nullptr, *channels[i].out,
                    i + 1 < count ? channels[i + 1].out : nullptr);
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
