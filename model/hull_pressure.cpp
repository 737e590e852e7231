#include "hull_pressure.hpp"

#include "arithmetic.hpp"
#include "dispersion.hpp"

#include <cmath>

namespace ocean::model {
namespace {

constexpr std::size_t kKeptEnvelopes = 64;  // a fleet's hulls on their legs' headings

int signed_bin(int i, int n) { return i < n / 2 ? i : i - n; }

}  // namespace

template <class Math>
HullPressure<Math>::HullPressure(int n, double size_m)
    : n_(n), columns_(n / 2 + 1), size_m_(size_m), row_phase_(n), column_phase_(columns_) {}

template <class Math>
const std::vector<double>& HullPressure<Math>::envelope(const HullPose& pose) {
  for (const Envelope& e : envelopes_)
    if (e.hull == pose.hull && e.dir_x == pose.dir_x && e.dir_z == pose.dir_z) return e.value;
  if (envelopes_.size() >= kKeptEnvelopes) envelopes_.erase(envelopes_.begin());
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
  return envelopes_.back().value;
}

template <class Math>
void HullPressure<Math>::add(const HullPose& pose, double scale, std::complex<double>* out) {
  const std::vector<double>& env = envelope(pose);
  // e^{-i k.x} = e^{-i kx x} e^{-i kz z}: one sine and cosine per row and column.
  for (int c = 0; c < columns_; ++c) {
    const double phase = kTwoPi * signed_bin(c, n_) / size_m_ * pose.x_m;
    column_phase_[c] = {Math::cos(phase), -Math::sin(phase)};
  }
  for (int r = 0; r < n_; ++r) {
    const double phase = kTwoPi * signed_bin(r, n_) / size_m_ * pose.z_m;
    row_phase_[r] = {scale * Math::cos(phase), -(scale * Math::sin(phase))};
  }
  for (int r = 0; r < n_; ++r) {
    const std::complex<double> row = row_phase_[r];
    const double* e = env.data() + static_cast<std::size_t>(r) * columns_;
    std::complex<double>* o = out + static_cast<std::size_t>(r) * columns_;
    for (int c = 0; c < columns_; ++c) {
      // (row * column) * envelope, written out so every language multiplies in the same order.
      const std::complex<double> k = column_phase_[c];
      const double re = row.real() * k.real() - row.imag() * k.imag();
      const double im = row.real() * k.imag() + row.imag() * k.real();
      o[c] = {o[c].real() + re * e[c], o[c].imag() + im * e[c]};
    }
  }
}

template class HullPressure<Libm>;
template class HullPressure<Det>;

}  // namespace ocean::model
