// Coefficient tables, the two-step recurrence, synthesis of heights, slopes and choppy channels,
// correction folding.
#include "modal_model.hpp"

#include "det_math.hpp"
#include "field_conversion.hpp"
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

// A state value as binary32 (CODEC.md 7.2): through double, as every language can.
float to_binary32(std::int64_t v) { return static_cast<float>(static_cast<double>(v)); }

}  // namespace

ModalModel::ModalModel(const StreamConfig& config)
    : n_(require_valid(config).grid),
      log2n_(config.grid_log2()),
      normals_(config.normals),
      choppy_(config.choppy),
      patch_x_m_(config.patch_x_m),
      patch_z_m_(config.patch_z_m),
      fft_(config.grid),
      float_fft_(config.grid) {
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
  kx_.assign(hc, 0.0f);
  kz_.assign(n, 0.0f);
  if (normals_) {
    for (int c = 0; c < n / 2; ++c) kx_[c] = static_cast<float>(kTwoPi * c / config.patch_x_m * factor);
    for (int r = 0; r < n; ++r)
      if (r != n / 2) kz_[r] = static_cast<float>(kTwoPi * signed_index(r, n) / config.patch_z_m * factor);
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
  zf_re_.resize(nn);
  zf_im_.resize(nn);
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

void ModalModel::build_choppy_factors(double choppiness) {
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
    choppy_factor_[j].resize(m);
    for (std::size_t i = 0; i < m; ++i) choppy_factor_[j][i] = static_cast<float>(choppiness * ratio_[j][i] * factor);
  }
  factor_choppiness_ = choppiness;
}

void ModalModel::synthesize_pair(const float* ar, const float* ai, const float* br, const float* bi,
                                 std::vector<std::int64_t>& a, std::vector<std::int64_t>* b) {
  const int n = n_, hc = n / 2 + 1;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  const double scale = std::ldexp(1.0, -2 * log2n_);
  for (int r = 0; r < n; ++r) {
    const int rm = (n - r) % n;
    for (int c = 0; c < hc; ++c) {
      const std::size_t h = static_cast<std::size_t>(r) * hc + c;
      // Z = A + iB: one inverse FFT gives A (real part) and B (imaginary part).
      const float xr = ar[h], xi = ai[h], yr = br ? br[h] : 0.0f, yi = bi ? bi[h] : 0.0f;
      const std::size_t at = static_cast<std::size_t>(r) * n + c;
      zf_re_[at] = xr - yi;
      zf_im_[at] = xi + yr;
      if (c > 0 && c < n / 2) {  // the conjugate partner -k
        const std::size_t mat = static_cast<std::size_t>(rm) * n + (n - c);
        zf_re_[mat] = xr + yi;
        zf_im_[mat] = yr - xi;
      }
    }
  }
  float_fft_.inverse_2d(zf_re_.data(), zf_im_.data());
  a.resize(nn);
  round_fields(zf_re_.data(), nn, scale, a.data());
  if (!b) return;
  b->resize(nn);
  round_fields(zf_im_.data(), nn, scale, b->data());
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out) {
  const int n = n_, hc = n / 2 + 1;
  const std::size_t m = static_cast<std::size_t>(half_size());
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  h_re_.resize(m);
  h_im_.resize(m);
  for (std::size_t h = 0; h < m; ++h) {
    h_re_[h] = to_binary32(cur.re[h]);
    h_im_[h] = to_binary32(cur.im[h]);
  }
  const float* hre = h_re_.data();
  const float* him = h_im_.data();
  // The channels in order - height, [slope_x, slope_z], [disp_x, disp_z, disp_xx, disp_zz,
  // disp_xz] - as half-spectra, synthesized in consecutive pairs (CODEC.md 7.2).
  struct Channel {
    const float *re, *im;
    std::vector<std::int64_t>* out;
  };
  Channel channels[8];
  int count = 0;
  channels[count++] = {hre, him, &out.height};
  if (normals_) {
    for (int j = 0; j < 4; ++j) spec_[j].resize(m);
    float *sxr = spec_[0].data(), *sxi = spec_[1].data(), *szr = spec_[2].data(), *szi = spec_[3].data();
    for (int r = 0; r < n; ++r) {
      const float kz = kz_[r];
      for (int c = 0; c < hc; ++c) {
        const std::size_t h = static_cast<std::size_t>(r) * hc + c;
        const float kx = kx_[c];
        sxr[h] = -(kx * him[h]);  // i kx H
        sxi[h] = kx * hre[h];
        szr[h] = -(kz * him[h]);
        szi[h] = kz * hre[h];
      }
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
    if (choppiness != factor_choppiness_) build_choppy_factors(choppiness);
    for (int j = 0; j < 5; ++j) {
      spec_[4 + 2 * j].resize(m);
      spec_[5 + 2 * j].resize(m);
      float* re = spec_[4 + 2 * j].data();
      float* im = spec_[5 + 2 * j].data();
      const float* g = choppy_factor_[j].data();
      if (j < 2) {  // displacement: -i G H
        for (std::size_t h = 0; h < m; ++h) {
          re[h] = g[h] * him[h];
          im[h] = -(g[h] * hre[h]);
        }
      } else {  // its derivatives: G H
        for (std::size_t h = 0; h < m; ++h) {
          re[h] = g[h] * hre[h];
          im[h] = g[h] * him[h];
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
