// Coefficient tables, the two-step recurrence, synthesis of heights, slopes and choppy channels,
// correction folding.
#include "modal_model.hpp"

#include "channel_pair.hpp"
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
  pair_scratch_.push_back(std::make_unique<PairScratch>(n));
}

void ModalModel::set_parallel(ParallelFor parallel) {
  parallel_ = std::move(parallel);
  const std::size_t slots = parallel_ ? 4 : 1;  // one per pair: at most eight channels
  while (pair_scratch_.size() < slots) pair_scratch_.push_back(std::make_unique<PairScratch>(n_));
  pair_scratch_.resize(slots);
}

ModalState ModalModel::zero_state() const {
  ModalState s;
  const std::size_t m = static_cast<std::size_t>(half_size());
  s.prev.re.assign(m, 0);
  s.prev.im.assign(m, 0);
  s.cur = s.prev;
  return s;
}

void ModalModel::advance(ModalState& s) const { advance(s, s, 1); }

void ModalModel::advance(ModalState& s, std::uint64_t steps) const { advance(s, s, steps); }

void ModalModel::advance(const ModalState& from, ModalState& out, std::uint64_t steps, const ParallelFor& parallel) const {
  const std::size_t m = a_.size();
  for (auto* v : {&out.prev.re, &out.prev.im, &out.cur.re, &out.cur.im}) v->resize(m);
  // Mode by mode, every step: each mode's recurrence is its own, so any split of the modes gives
  // the same integers. Each mode is read before it is written, so `out` may be `from`.
  const std::int64_t* a = a_.data();
  const auto modes = [&](const std::vector<std::int64_t>& prev, const std::vector<std::int64_t>& cur,
                         std::vector<std::int64_t>& out_prev, std::vector<std::int64_t>& out_cur, std::size_t begin,
                         std::size_t end) {
    if (steps == 1) {  // nearly every delta: one step, straight through
      for (std::size_t i = begin; i < end; ++i) {
        const std::int64_t p = prev[i], c = cur[i];
        out_prev[i] = c;
        out_cur[i] = wsub(mul_round_sym(a[i], c, kRecurrenceBits), p);
      }
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {
      std::int64_t p = prev[i], c = cur[i];
      for (std::uint64_t step = 0; step < steps; ++step) {
        const std::int64_t next = wsub(mul_round_sym(a[i], c, kRecurrenceBits), p);
        p = c;
        c = next;
      }
      out_prev[i] = p;
      out_cur[i] = c;
    }
  };
  const int parts = parallel ? kParallelParts : 1;
  run_jobs(parallel, parts, [&](int part) {
    const std::size_t begin = m * part / parts, end = m * (part + 1) / parts;
    modes(from.prev.re, from.cur.re, out.prev.re, out.cur.re, begin, end);
    modes(from.prev.im, from.cur.im, out.prev.im, out.cur.im, begin, end);
  });
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

void ModalModel::synthesize_pair(PairScratch& scratch, const FloatSpectrum& x, ChannelSource a, ChannelSource b,
                                 std::vector<std::int64_t>& a_out, std::vector<std::int64_t>* b_out) const {
  const std::size_t nn = static_cast<std::size_t>(n_) * n_;
  const double scale = std::ldexp(1.0, -2 * log2n_);
  pack_channel_pair(x, a, b, scratch.re.data(), scratch.im.data());
  scratch.fft.inverse_2d(scratch.re.data(), scratch.im.data());
  a_out.resize(nn);
  round_fields(scratch.re.data(), nn, scale, a_out.data());
  if (!b_out) return;
  b_out->resize(nn);
  round_fields(scratch.im.data(), nn, scale, b_out->data());
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out) {
  const std::size_t m = static_cast<std::size_t>(half_size());
  const std::size_t nn = static_cast<std::size_t>(n_) * n_;
  h_re_.resize(m);
  h_im_.resize(m);
  for (std::size_t h = 0; h < m; ++h) {
    h_re_[h] = to_binary32(cur.re[h]);
    h_im_[h] = to_binary32(cur.im[h]);
  }
  const FloatSpectrum x{n_, h_re_.data(), h_im_.data(), kx_.data(), kz_.data()};
  // The channels in order - height, [slope_x, slope_z], [disp_x, disp_z, disp_xx, disp_zz,
  // disp_xz] - synthesized in consecutive pairs (CODEC.md 7.2).
  struct Channel {
    ChannelSource source;
    std::vector<std::int64_t>* out;
  };
  Channel channels[8];
  int count = 0;
  channels[count++] = {{ChannelKind::height}, &out.height};
  if (normals_) {
    channels[count++] = {{ChannelKind::slope_x}, &out.slope_x};
    channels[count++] = {{ChannelKind::slope_z}, &out.slope_z};
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
    for (int j = 0; j < 5; ++j)
      channels[count++] = {{j < 2 ? ChannelKind::disp : ChannelKind::derivative, choppy_factor_[j].data()}, choppy_out[j]};
  } else {
    for (auto* f : choppy_out) f->clear();
  }
  const bool spread = pair_scratch_.size() > 1;
  run_jobs(spread ? parallel_ : ParallelFor{}, (count + 1) / 2, [&](int pair) {
    const Channel& a = channels[2 * pair];
    const Channel* b = 2 * pair + 1 < count ? &channels[2 * pair + 1] : nullptr;
    synthesize_pair(*pair_scratch_[spread ? pair : 0], x, a.source, b ? b->source : ChannelSource{}, *a.out,
                    b ? b->out : nullptr);
  });
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
