// Coefficient tables, the two-step recurrence (the wake's forced one too), the choppy factors,
// correction folding; the synthesis of the channels is modal_synthesis.cpp.
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

// G / lambda of a row (CODEC.md 7.2): kx^gx kz^gz, times |k| or divided by it per power of |k|.
double ratio_of(const ChannelFactor& f, double kx, double kz, double k) {
  double g = 1.0;
  for (int i = 0; i < f.gx; ++i) g *= kx;
  for (int i = 0; i < f.gz; ++i) g *= kz;
  for (int i = 0; i < f.gk; ++i) g *= k;
  for (int i = 0; i > f.gk; --i) g /= k;
  return f.sign < 0 ? -g : g;
}

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
  for (int ch = 0; ch < kChannelCount; ++ch) {
    unit_factor_[ch] = unit_scale(config, ChannelUnit::height) / unit_scale(config, kChannels[ch].unit);
  }
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

// G per mode without lambda (0 at DC and Nyquist), once per stream; then in float with the
// choppiness (the rows that carry it) and the channel's units (CODEC.md 7.2).
void ModalModel::build_factors(double choppiness) {
  const std::size_t m = a_.size();
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const ChannelInfo& info = kChannels[ch];
    if (!factored(info) || !carried(info, normals_, choppy_) || !ratio_[ch].empty()) continue;
    ratio_[ch].assign(m, 0.0);
    for (const StreamConfig::Lattice& l : lattices_) {
      const int n = l.n, hc = n / 2 + 1;
      for (int r = 0; r < n; ++r) {
        if (r == n / 2) continue;
        const double kz = model::kTwoPi * signed_index(r, n) / l.patch_z_m;
        for (int c = 0; c < n / 2; ++c) {
          const double kx = model::kTwoPi * c / l.patch_x_m;
          const double k = std::sqrt(kx * kx + kz * kz);
          if (k != 0.0) ratio_[ch][l.modes_at + static_cast<std::size_t>(r) * hc + c] = ratio_of(info.factor, kx, kz, k);
        }
      }
    }
  }
  for (int ch = 0; ch < kChannelCount; ++ch) {
    if (ratio_[ch].empty()) continue;
    channel_factor_[ch].resize(m);
    const bool scaled = kChannels[ch].factor.choppy;
    for (std::size_t i = 0; i < m; ++i)
      channel_factor_[ch][i] = static_cast<float>(scaled ? choppiness * ratio_[ch][i] * unit_factor_[ch]
                                                         : ratio_[ch][i] * unit_factor_[ch]);
  }
  factor_choppiness_ = choppiness;
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
