// The small-wave filter around each spectrum's shape, and the choice of shape.
#include "spectrum.hpp"

#include "arithmetic.hpp"
#include "spectra/jonswap.hpp"
#include "spectra/phillips.hpp"

#include <algorithm>

namespace ocean::model {
namespace {

template <class Math>
std::shared_ptr<const SpectrumShape<Math>> shape_of(const SceneParams& p) {
  switch (p.spectrum) {
    case SpectrumKind::phillips: return std::make_shared<Phillips<Math>>(p);
    case SpectrumKind::jonswap: return std::make_shared<Jonswap<Math>>(p);
  }
  throw ParamError("spectrum " + std::to_string(static_cast<int>(p.spectrum)) + " has no shape");
}

}  // namespace

double default_small_wave(const SceneParams& p) {
  // Half the coarser grid spacing: at the Nyquist wavenumber pi/dx the filter exp(-k^2 l^2) is
  // exp(-pi^2/4) = 0.085 in energy, which tames aliasing of the slopes without flattening the grid.
  return 0.5 * std::max(p.patch_x_m / p.size_x, p.patch_z_m / p.size_z);
}

template <class Math>
Spectrum<Math>::Spectrum(const SceneParams& p)
    : wind_speed_(p.wind_speed_mps),
      amplitude_(p.amplitude),
      small_wave_m_(p.small_wave_m > 0.0 ? p.small_wave_m : default_small_wave(p)),
      shape_(shape_of<Math>(p)) {}

template <class Math>
double Spectrum<Math>::density(double kx, double kz) const {
  const double k = Math::hypot(kx, kz);
  if (k == 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
  const double filter = Math::exp(-k * k * small_wave_m_ * small_wave_m_);
  if (filter == 0.0) return 0.0;
  return shape_->density(kx, kz, k) * filter;
}

template class Spectrum<Libm>;
template class Spectrum<Det>;

}  // namespace ocean::model
