// Coefficient tables, the two-step recurrence, synthesis of heights, slopes and choppy channels,
// correction folding.
#include "modal_model.hpp"

#include "channel_pair.hpp"
#include "arithmetic.hpp"
#include "dispersion.hpp"
#include "scene_params.hpp"
#include "fft_bin.hpp"
#include "field_conversion.hpp"
#include "fixed_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace ocean::codec {
namespace {

const StreamConfig& require_valid(const StreamConfig& config) {
  const std::string err = validate(config);
  if (!err.empty()) throw std::invalid_argument("stream config: " + err);
  return config;
}

// The wake's damped oscillator sampled every dt (CODEC.md 7.9): the roots of x^2 - a x + b are
// e^{(-g +- i wd) dt}, or e^{-(g -+ r) dt} for an overdamped mode; b = e^{-2 g dt} either way.
// `stay` is how much of a displacement held still is left after dt (the propagator's
// position-to-position term), which shapes the response to pressure held over a step.
struct Damped {
  double a, b, stay;
};
Damped damped_recurrence(double w, double g, double dt) {
  if (w > g) {
    const double wd = std::sqrt(w * w - g * g), e = model::det_exp_neg(g * dt);
    const double c = model::det_cos(wd * dt), s = model::det_sin(wd * dt);
    return {2.0 * e * c, model::det_exp_neg(2.0 * g * dt), e * (c + g * (s / wd))};
  }
  const double r = std::sqrt(g * g - w * w);
  if (g + r == 0.0) return {2.0, 1.0, 1.0};  // the mean level of undamped water: it stays
  // g - r as w^2 / (g + r): no cancellation when the damping is strong.
  const double slow = model::det_exp_neg(w * w / (g + r) * dt), fast = model::det_exp_neg((g + r) * dt);
  const double sd = r * dt < 1e-8 ? model::det_exp_neg(g * dt) * dt : 0.5 * (slow - fast) / r;
  return {slow + fast, model::det_exp_neg(2.0 * g * dt), 0.5 * (slow + fast) + g * sd};
}

// Nearest integer (halves up), saturated at +-2^62, 0 for NaN: a forcing term from any hull.
std::int64_t forcing_units(double x) {
  constexpr double kLimit = 0x1.0p62;
  if (!(x == x)) return 0;
  if (x >= kLimit) return static_cast<std::int64_t>(kLimit);
  if (x <= -kLimit) return -static_cast<std::int64_t>(kLimit);
  return static_cast<std::int64_t>(std::floor(x + 0.5));
}

// A state value as binary32 (CODEC.md 7.2): through double, as every language can.
float to_binary32(std::int64_t v) { return static_cast<float>(static_cast<double>(v)); }

}  // namespace

ModalModel::ModalModel(const StreamConfig& config)
    : lattices_(require_valid(config).lattices()),
      samples_(config.samples()),
      normals_(config.normals),
      choppy_(config.choppy) {
  const double dt = config.dt_s();  // one tick step: deltas advance (tick - baseline) steps
  // d/dx in spectral space is i kx; the factor converts height units per metre to slope units.
  const double factor = (static_cast<double>(config.height_step_m) / 65536.0) /
                        (static_cast<double>(config.slope_step) / 4096.0);
  disp_factor_ = (static_cast<double>(config.height_step_m) / 65536.0) / (static_cast<double>(config.disp_step_m) / 65536.0);
  jac_factor_ = factor;
  std::size_t largest = 0;
  wake_at_ = config.modes();
  for (const StreamConfig::Lattice& l : lattices_) {
    const int n = l.n, hc = n / 2 + 1;
    if (l.wake) wake_at_ = l.modes_at;
    for (int r = 0; r < n; ++r) {
      const double kz = model::kTwoPi * signed_index(r, n) / l.patch_z_m;
      for (int c = 0; c < hc; ++c) {
        const double kx = model::kTwoPi * signed_index(c, n) / l.patch_x_m;
        const double k = std::sqrt(kx * kx + kz * kz);
        const double w = model::angular_frequency<model::Det>(k, config.gravity_mps2, model::scene_depth(config.depth_m));
        if (!l.wake) {
          a_.push_back(model::to_fixed(2.0 * model::det_cos(w * dt), kRecurrenceBits));
          continue;
        }
        const double g = config.wake.decay_per_s + 2.0 * config.wake.viscosity_m2ps * (k * k);
        const Damped d = damped_recurrence(w, g, dt);
        a_.push_back(model::to_fixed(d.a, kRecurrenceBits));
        b_.push_back(model::to_fixed(d.b, kRecurrenceBits));
        // Pressure p held over each step adds alpha p(t-1) + beta p(t) (CODEC.md 7.9); the
        // Nyquist row and column are not forced (a real field cannot hold them as a hull would).
        const bool nyquist = r == n / 2 || c == n / 2;
        alpha_.push_back(nyquist ? 0.0 : d.a - d.b - d.stay);
        beta_.push_back(nyquist ? 0.0 : d.stay - 1.0);
      }
    }
    auto grid = std::make_unique<Grid>(n);
    grid->kx.assign(hc, 0.0f);
    grid->kz.assign(n, 0.0f);
    if (normals_) {
      for (int c = 0; c < n / 2; ++c) grid->kx[c] = static_cast<float>(model::kTwoPi * c / l.patch_x_m * factor);
      for (int r = 0; r < n; ++r)
        if (r != n / 2) grid->kz[r] = static_cast<float>(model::kTwoPi * signed_index(r, n) / l.patch_z_m * factor);
    }
    for (int r = 0; r < n; ++r) {
      if (r == n / 2) continue;
      for (int c = 0; c < n / 2; ++c) {
        if (c == 0 && !(r >= 1 && r < n / 2)) continue;
        key_modes_.push_back(static_cast<std::int32_t>(l.modes_at) + r * hc + c);
      }
    }
    grid->pair_scratch.push_back(std::make_unique<PairScratch>(n));
    grids_.push_back(std::move(grid));
    largest = std::max(largest, static_cast<std::size_t>(n) * n);
  }
  z_re_.resize(largest);
  z_im_.resize(largest);
}

void ModalModel::set_parallel(ParallelFor parallel) {
  parallel_ = std::move(parallel);
  const std::size_t slots = parallel_ ? 4 : 1;  // one per pair: at most eight channels
  for (std::size_t g = 0; g < grids_.size(); ++g) {
    auto& scratch = grids_[g]->pair_scratch;
    while (scratch.size() < slots) scratch.push_back(std::make_unique<PairScratch>(lattices_[g].n));
    scratch.resize(slots);
  }
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

void ModalModel::advance(const ModalState& from, ModalState& out, std::uint64_t steps, const ParallelFor& parallel,
                         WakeForcing* forcing, Tick first) const {
  const std::size_t m = forcing ? wake_at_ : a_.size();  // with forcing, the wake's modes below
  for (auto* v : {&out.prev.re, &out.prev.im, &out.cur.re, &out.cur.im}) v->resize(a_.size());
  // Mode by mode, every step: each mode's recurrence is its own, so any split of the modes gives
  // the same integers. Each mode is read before it is written, so `out` may be `from`.
  const std::int64_t* a = a_.data();
  const auto damped = [&](const std::vector<std::int64_t>& prev, const std::vector<std::int64_t>& cur,
                          std::vector<std::int64_t>& out_prev, std::vector<std::int64_t>& out_cur, std::size_t begin,
                          std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::int64_t p = prev[i], c = cur[i];
      for (std::uint64_t step = 0; step < steps; ++step) {
        const std::int64_t next =
            wsub(mul_round_sym(a[i], c, kRecurrenceBits), mul_round_sym(b_[i - wake_at_], p, kRecurrenceBits));
        p = c;
        c = next;
      }
      out_prev[i] = p;
      out_cur[i] = c;
    }
  };
  const auto modes = [&](const std::vector<std::int64_t>& prev, const std::vector<std::int64_t>& cur,
                         std::vector<std::int64_t>& out_prev, std::vector<std::int64_t>& out_cur, std::size_t begin,
                         std::size_t end) {
    if (end > wake_at_) {
      damped(prev, cur, out_prev, out_cur, std::max(begin, wake_at_), end);
      end = std::max(begin, wake_at_);
    }
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
  if (forcing) advance_forced_wake(from, out, steps, *forcing, first);
}

void ModalModel::advance_forced_wake(const ModalState& from, ModalState& out, std::uint64_t steps, WakeForcing& forcing,
                                     Tick first) const {
  const std::size_t begin = wake_at_;
  if (&from != &out)
    for (auto [src, dst] : {std::pair{&from.prev.re, &out.prev.re}, std::pair{&from.prev.im, &out.prev.im},
                            std::pair{&from.cur.re, &out.cur.re}, std::pair{&from.cur.im, &out.cur.im}})
      std::copy(src->begin() + static_cast<std::ptrdiff_t>(begin), src->end(), dst->begin() + static_cast<std::ptrdiff_t>(begin));
  step_wake({out.prev.re.data() + begin, out.prev.im.data() + begin, out.cur.re.data() + begin, out.cur.im.data() + begin},
            steps, first, &forcing, 0, std::numeric_limits<std::int64_t>::max());
}

// Tick by tick, since each tick's forcing is every mode's: X(t+1) = a X(t) - b X(t-1) + F(t),
// F(t) = alpha P(t-1) + beta P(t) rounded to units, P(t) the hulls' pressure during the step from
// t, taken as 0 outside [force_from, force_until).
void ModalModel::step_wake(WakeSpan s, std::uint64_t steps, Tick first, WakeForcing* forcing, std::int64_t force_from,
                           std::int64_t force_until) const {
  const std::size_t count = a_.size() - wake_at_;
  const std::int64_t* a = a_.data() + wake_at_;
  const auto forced = [&](Tick t) {
    const auto signed_t = static_cast<std::int64_t>(t);
    return forcing && signed_t >= force_from && signed_t < force_until;
  };
  std::vector<double> f_re(count), f_im(count);
  for (std::uint64_t step = 0; step < steps; ++step) {
    const Tick t = first + step;
    std::fill(f_re.begin(), f_re.end(), 0.0);
    std::fill(f_im.begin(), f_im.end(), 0.0);
    if (forced(t - 1)) {
      const std::vector<std::complex<double>>& before = forcing->pressure(t - 1);
      for (std::size_t i = 0; i < count; ++i) {
        f_re[i] = alpha_[i] * before[i].real();
        f_im[i] = alpha_[i] * before[i].imag();
      }
    }
    if (forced(t)) {
      const std::vector<std::complex<double>>& during = forcing->pressure(t);
      for (std::size_t i = 0; i < count; ++i) {
        f_re[i] = f_re[i] + beta_[i] * during[i].real();
        f_im[i] = f_im[i] + beta_[i] * during[i].imag();
      }
    }
    for (std::size_t i = 0; i < count; ++i)
      for (auto [prev, cur, f] : {std::tuple{s.prev_re, s.cur_re, f_re[i]}, std::tuple{s.prev_im, s.cur_im, f_im[i]}}) {
        const std::int64_t p = prev[i], c = cur[i];
        prev[i] = c;
        cur[i] = wadd(wsub(mul_round_sym(a[i], c, kRecurrenceBits), mul_round_sym(b_[i], p, kRecurrenceBits)),
                      forcing_units(f));
      }
  }
}

void ModalModel::build_choppy_factors(double choppiness) {
  const std::size_t m = a_.size();
  if (ratio_[0].empty()) {
    for (auto& r : ratio_) r.assign(m, 0.0);
    for (const StreamConfig::Lattice& l : lattices_) {
      const int n = l.n, hc = n / 2 + 1;
      for (int r = 0; r < n; ++r) {
        if (r == n / 2) continue;
        const double kz = model::kTwoPi * signed_index(r, n) / l.patch_z_m;
        for (int c = 0; c < n / 2; ++c) {
          const double kx = model::kTwoPi * c / l.patch_x_m;
          const double k = std::sqrt(kx * kx + kz * kz);
          if (k == 0.0) continue;
          const std::size_t at = l.modes_at + static_cast<std::size_t>(r) * hc + c;
          ratio_[0][at] = kx / k;
          ratio_[1][at] = kz / k;
          ratio_[2][at] = (kx * kx) / k;
          ratio_[3][at] = (kz * kz) / k;
          ratio_[4][at] = (kx * kz) / k;
        }
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
                                 float* a_out, float* b_out) const {
  float* b_or_discard = b_out ? b_out : scratch.discard.data();
  pack_channel_pair(x, a, b, a_out, b_or_discard);
  scratch.fft.inverse_2d(a_out, b_or_discard);
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, UnroundedFields& out) {
  synthesize_channels(cur, choppiness, out, nullptr);
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out) {
  std::vector<std::int64_t>* fields[kCorrectionChannels] = {&out.height, &out.slope_x, &out.slope_z,  &out.disp_x,
                                                            &out.disp_z, &out.disp_xx, &out.disp_zz, &out.disp_xz};
  synthesize_channels(cur, choppiness, unrounded_, fields);
}

// The channels in order - height, [slope_x, slope_z], [disp_x, disp_z, disp_xx, disp_zz, disp_xz] -
// that have a transform this frame, sized; the others cleared (not streamed) or zeroed. They are
// synthesized in consecutive pairs (CODEC.md 7.2), lattice by lattice.
int ModalModel::plan_channels(double choppiness, UnroundedFields& out, std::vector<std::int64_t>* const* rounded,
                              SynthesisChannel* channels) {
  int count = 0;
  const std::size_t nn = samples_;
  // A channel without a transform: not streamed (cleared), or exactly 0 everywhere.
  const auto without_transform = [&](int index, bool zeros) {
    out.channels[index].assign(zeros ? nn : 0, 0.0f);
    if (rounded) rounded[index]->assign(zeros ? nn : 0, 0);
  };
  channels[count++] = {0, ChannelKind::height, nullptr};
  for (int j = 1; j <= 2; ++j) {
    if (normals_) channels[count++] = {j, j == 1 ? ChannelKind::slope_x : ChannelKind::slope_z, nullptr};
    else without_transform(j, false);
  }
  // A choppy stream at choppiness 0: every factor is 0, so every field is exactly 0.
  const bool choppy_transforms = choppy_ && choppiness != 0.0;
  if (choppy_transforms && choppiness != factor_choppiness_) build_choppy_factors(choppiness);
  for (int j = 0; j < 5; ++j) {
    if (choppy_transforms)
      channels[count++] = {3 + j, j < 2 ? ChannelKind::disp : ChannelKind::derivative, choppy_factor_[j].data()};
    else without_transform(3 + j, choppy_);
  }
  for (int i = 0; i < count; ++i) {
    out.channels[channels[i].index].resize(nn);
    if (rounded) rounded[channels[i].index]->resize(nn);
  }
  return count;
}

void ModalModel::synthesize_channels(const HalfSpectrum& cur, double choppiness, UnroundedFields& out,
                                     std::vector<std::int64_t>* const* rounded) {
  const std::size_t m = a_.size();
  h_re_.resize(m);
  h_im_.resize(m);
  for (std::size_t h = 0; h < m; ++h) {
    h_re_[h] = to_binary32(cur.re[h]);
    h_im_[h] = to_binary32(cur.im[h]);
  }
  SynthesisChannel channels[kCorrectionChannels];
  const int count = plan_channels(choppiness, out, rounded, channels);
  for (std::size_t g = 0; g < grids_.size(); ++g) {
    const StreamConfig::Lattice& l = lattices_[g];
    Grid& grid = *grids_[g];
    const FloatSpectrum x{l.n, h_re_.data() + l.modes_at, h_im_.data() + l.modes_at, grid.kx.data(), grid.kz.data()};
    const auto source = [&](const SynthesisChannel& c) {
      return ChannelSource{c.kind, c.factor ? c.factor + l.modes_at : nullptr};
    };
    const std::size_t lattice_samples = static_cast<std::size_t>(l.n) * l.n;
    const double scale = synthesis_scale(l.n);
    const auto slice = [&](const SynthesisChannel& c) { return out.channels[c.index].data() + l.samples_at; };
    const bool spread = grid.pair_scratch.size() > 1;
    run_jobs(spread ? parallel_ : ParallelFor{}, (count + 1) / 2, [&](int pair) {
      const SynthesisChannel& a = channels[2 * pair];
      const SynthesisChannel* b = 2 * pair + 1 < count ? &channels[2 * pair + 1] : nullptr;
      synthesize_pair(*grid.pair_scratch[spread ? pair : 0], x, source(a), b ? source(*b) : ChannelSource{}, slice(a),
                      b ? slice(*b) : nullptr);
      if (!rounded) return;
      for (const SynthesisChannel* c : {&a, b})
        if (c) round_fields(slice(*c), lattice_samples, scale, rounded[c->index]->data() + l.samples_at);
    });
  }
}

void ModalModel::spectrum_of(const std::int64_t* field, HalfSpectrum& out) {
  out.re.resize(a_.size());
  out.im.resize(a_.size());
  for (std::size_t g = 0; g < grids_.size(); ++g) lattice_spectrum(g, field, out);
}

void ModalModel::lattice_spectrum(std::size_t g, const std::int64_t* all_fields, HalfSpectrum& all) {
  const StreamConfig::Lattice& l = lattices_[g];
  const int n = l.n, hc = n / 2 + 1;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  const std::int64_t* field = all_fields + l.samples_at;
  for (std::size_t i = 0; i < nn; ++i) {
    z_re_[i] = field[i];
    z_im_[i] = 0;
  }
  grids_[g]->fft.forward_2d(z_re_.data(), z_im_.data());
  std::int64_t* re = all.re.data() + l.modes_at;
  std::int64_t* im = all.im.data() + l.modes_at;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < hc; ++c) {
      re[r * hc + c] = z_re_[static_cast<std::size_t>(r) * n + c];
      im[r * hc + c] = z_im_[static_cast<std::size_t>(r) * n + c];
    }
  // Columns kx = 0 and kx = n/2 hold both k and -k: take the rows up to n/2 as the truth.
  for (int c : {0, n / 2}) {
    for (int r = n / 2 + 1; r < n; ++r) {
      re[r * hc + c] = re[(n - r) * hc + c];
      im[r * hc + c] = -im[(n - r) * hc + c];
    }
    im[c] = 0;
    im[(n / 2) * hc + c] = 0;
  }
}

void ModalModel::add_correction(ModalState& s, const std::vector<std::int64_t>& field, std::uint64_t lag) {
  HalfSpectrum d;
  spectrum_of(field.data(), d);
  for (std::size_t i = 0; i < d.re.size(); ++i) {
    s.cur.re[i] = wadd(s.cur.re[i], d.re[i]);
    s.cur.im[i] = wadd(s.cur.im[i], d.im[i]);
    if (i >= wake_at_ && lag != 0) {
      s.prev.re[i] = wadd(s.prev.re[i], wsub(d.re[i], div_round_sym(d.re[i], kWakeVelocityShare * lag)));
      s.prev.im[i] = wadd(s.prev.im[i], wsub(d.im[i], div_round_sym(d.im[i], kWakeVelocityShare * lag)));
      continue;
    }
    s.prev.re[i] = wadd(s.prev.re[i], d.re[i]);
    s.prev.im[i] = wadd(s.prev.im[i], d.im[i]);
  }
}

void ModalModel::mirror_key_column(HalfSpectrum& s) const {
  for (const StreamConfig::Lattice& l : lattices_) {
    const int n = l.n, hc = n / 2 + 1;
    std::int64_t* re = s.re.data() + l.modes_at;
    std::int64_t* im = s.im.data() + l.modes_at;
    for (int r = n / 2 + 1; r < n; ++r) {
      re[r * hc] = re[(n - r) * hc];
      im[r * hc] = -im[(n - r) * hc];
    }
  }
}

}  // namespace ocean::codec
