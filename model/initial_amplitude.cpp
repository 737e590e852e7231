// h0(k) = xi sqrt(P dk^2 / 2) with a hashed Box-Muller xi.
#include "initial_amplitude.hpp"

#include "arithmetic.hpp"
#include "mode_gaussian.hpp"

#include <cmath>

namespace ocean::model {

template <class Math>
std::complex<double> initial_amplitude(const SceneParams& p, const Spectrum<Math>& spectrum, int kx, int kz) {
  if ((kx == 0 && kz == 0) || !p.band.keeps(kx, kz)) return {};
  const double dkx = wavenumber(1, p.patch_x_m);
  const double dkz = wavenumber(1, p.patch_z_m);
  const double variance = spectrum.density(kx * dkx, kz * dkz) * dkx * dkz;
  if (!(variance > 1e-40)) return {};  // below 1e-20 m of amplitude; also catches NaN
  const GaussianPair xi = mode_gaussian<Math>(p.seed, kx, kz);
  // 1/sqrt(2) makes xi a unit complex Gaussian, the other 1/sqrt(2) is the sqrt(P dk^2 / 2).
  const double scale = std::sqrt(variance) * 0.5;
  return {xi.re * scale, xi.im * scale};
}

template std::complex<double> initial_amplitude<Libm>(const SceneParams&, const Spectrum<Libm>&, int, int);
template std::complex<double> initial_amplitude<Det>(const SceneParams&, const Spectrum<Det>&, int, int);

}  // namespace ocean::model
