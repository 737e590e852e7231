#include "hull_pressure.hpp"

#include "arithmetic.hpp"
#include "dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ocean::model {
namespace {

constexpr std::size_t kKeptEnvelopes = 64;  // a fleet's hulls on their legs' headings

static_assert(kKeptEnvelopes > HullPressure<Libm>::kMaxHulls, "a call's hulls must fit among the kept envelopes");

int signed_bin(int i, int n) { return i < n / 2 ? i : i - n; }

// One hull's row: o += (row * column) * envelope, written out so every language multiplies in the
// same order. Built for AVX2 too where the CPU has it: the same multiplies and adds, four wide
// (no FMA, no reordering), so every CPU computes the same bits.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define OCEAN_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define OCEAN_AVX2_CLONE
#endif
OCEAN_AVX2_CLONE void add_row(double* o, double row_re, double row_im,
                                                              const double* column_re, const double* column_im,
                                                              const double* e, std::size_t columns) {
  for (std::size_t c = 0; c < columns; ++c) {
    const double re = row_re * column_re[c] - row_im * column_im[c];
    const double im = row_re * column_im[c] + row_im * column_re[c];
    o[2 * c] += re * e[c];
    o[2 * c + 1] += im * e[c];
  }
}

}  // namespace

template <class Math>
HullPressure<Math>::HullPressure(int n, double size_m)
    : n_(n), columns_(n / 2 + 1), size_m_(size_m) {}

template <class Math>
bool HullPressure<Math>::Envelope::fits(const HullPose& pose) const {
  return hull == pose.hull && dir_x == pose.dir_x && dir_z == pose.dir_z;
}

template <class Math>
const double* HullPressure<Math>::envelope(const HullPose& pose, std::span<const HullPose> in_use) {
  for (const Envelope& e : envelopes_)
    if (e.fits(pose)) return e.value.data();
  if (envelopes_.size() >= kKeptEnvelopes) {
    // The oldest that no hull of this call needs (a call has at most kMaxHulls).
    const auto unused = std::find_if(envelopes_.begin(), envelopes_.end(), [&](const Envelope& e) {
      return std::none_of(in_use.begin(), in_use.end(), [&](const HullPose& p) { return e.fits(p); });
    });
    envelopes_.erase(unused);
  }
  Envelope e{pose.hull, pose.dir_x, pose.dir_z, {}};
  const double sa = 0.25 * pose.hull.length_m, sc = 0.25 * pose.hull.beam_m;
  const double peak = pose.hull.draft_m * (kTwoPi * sa * sc) / (size_m_ * size_m_);
  e.value.resize(static_cast<std::size_t>(n_) * columns_);
  for (int r = 0; r < n_; ++r) {
    const double kz = kTwoPi * signed_bin(r, n_) / size_m_;
    for (int c = 0; c < columns_; ++c) {
      const double kx = kTwoPi * signed_bin(c, n_) / size_m_;
      const double ka = kx * pose.dir_x + kz * pose.dir_z, kc = kz * pose.dir_x - kx * pose.dir_z;
      const double y = 0.5 * (sa * sa * (ka * ka) + sc * sc * (kc * kc));
      e.value[static_cast<std::size_t>(r) * columns_ + c] = peak * Math::exp(-y);
    }
  }
  envelopes_.push_back(std::move(e));
  return envelopes_.back().value.data();
}

template <class Math>
void HullPressure<Math>::power_phases(double step, double scale, double* column_re, double* column_im,
                                      std::complex<double>* rows) const {
  // scale e^{-i b step} for the signed bins b of the columns (0 .. n/2 - 1, then -n/2) or of the
  // rows (FFT order), walking out from bin 0 each way.
  constexpr int kDirectEvery = 16;
  const auto direct = [&](int b) {
    return std::complex<double>(scale * Math::cos(b * step), -(scale * Math::sin(b * step)));
  };
  const auto walk = [&](int sign, int count, auto&& store) {
    const std::complex<double> unit(Math::cos(step), -(sign * Math::sin(step)));
    std::complex<double> current;
    for (int i = 0; i < count; ++i) {
      // Written out, so every language multiplies in the same order.
      current = i % kDirectEvery == 0 ? direct(sign * i)
                                      : std::complex<double>(current.real() * unit.real() - current.imag() * unit.imag(),
                                                             current.real() * unit.imag() + current.imag() * unit.real());
      store(i, current);
    }
  };
  const int half = n_ / 2;
  if (rows) {
    walk(+1, half, [&](int i, std::complex<double> v) { rows[i] = v; });
    walk(-1, half + 1, [&](int i, std::complex<double> v) {
      if (i > 0) rows[n_ - i] = v;
    });
  } else {
    const auto store = [&](int c, std::complex<double> v) {
      column_re[c] = v.real();
      column_im[c] = v.imag();
    };
    walk(+1, half, store);
    store(half, direct(-half));
  }
}

template <class Math>
void HullPressure<Math>::add(std::span<const HullPose> poses, double scale, std::complex<double>* out) {
  if (poses.size() > kMaxHulls) throw std::invalid_argument("HullPressure: more than kMaxHulls hulls in one call");
  const std::size_t hulls = poses.size();
  const std::size_t columns = static_cast<std::size_t>(columns_);
  // e^{-i k.x} = e^{-i kx x} e^{-i kz z}: each hull's column and row phases, walked as powers of
  // the first bin's with a direct sine every 16 bins (a sixteenth of the sines, within 1e-14 of
  // the direct ones; CODEC.md 7.9 writes the walk out).
  column_re_.resize(hulls * columns);
  column_im_.resize(hulls * columns);
  row_phase_.resize(hulls * n_);
  for (std::size_t h = 0; h < hulls; ++h) {
    power_phases(kTwoPi / size_m_ * poses[h].x_m, 1.0, column_re_.data() + h * columns, column_im_.data() + h * columns,
                 nullptr);
    power_phases(kTwoPi / size_m_ * poses[h].z_m, scale, nullptr, nullptr, row_phase_.data() + h * n_);
  }
  // Every envelope first (making one may drop an old one), then their addresses, which stay put.
  for (const HullPose& pose : poses) (void)envelope(pose, poses);
  envelope_of_.clear();
  for (const HullPose& pose : poses) envelope_of_.push_back(envelope(pose, poses));
  // Row by row, every hull in turn, so a row of `out` stays in cache while the hulls add to it;
  // each mode still sums the hulls in their order.
  for (int r = 0; r < n_; ++r) {
    // Interleaved real and imaginary parts (std::complex's layout), written on flat arrays so the
    // loop vectorises.
    double* o = reinterpret_cast<double*>(out + static_cast<std::size_t>(r) * columns);
    for (std::size_t h = 0; h < hulls; ++h) {
      add_row(o, row_phase_[h * n_ + r].real(), row_phase_[h * n_ + r].imag(), column_re_.data() + h * columns,
              column_im_.data() + h * columns, envelope_of_[h] + static_cast<std::size_t>(r) * columns, columns);
    }
  }
}

template class HullPressure<Libm>;
template class HullPressure<Det>;

}  // namespace ocean::model
