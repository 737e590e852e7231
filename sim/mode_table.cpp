// Building a band's ModeTable from h0 and the dispersion relation.
#include "mode_table.hpp"

#include "sea_model.hpp"

#include <cmath>
#include <complex>

namespace ocean::sim {

ModeTable build_mode_table(const SceneParams& p, const Spectrum& spectrum, int n_x, int n_z) {
  ModeTable t;
  t.n_x = n_x;
  t.n_z = n_z;
  t.columns = n_x / 2 + 1;
  t.kx.resize(t.columns);
  t.kz.resize(n_z);
  const std::size_t count = t.modes();
  t.omega.assign(count, 0.0);
  t.sum_re.assign(count, 0.0f);
  t.sum_im.assign(count, 0.0f);
  t.diff_re.assign(count, 0.0f);
  t.diff_im.assign(count, 0.0f);

  for (int i = 0; i < t.columns; ++i) t.kx[i] = static_cast<float>(wavenumber(i, p.patch_x_m));
  for (int j = 0; j < n_z; ++j) t.kz[j] = static_cast<float>(wavenumber(t.kz_index(j), p.patch_z_m));

  for (int j = 0; j < n_z; ++j) {
    const int kz = t.kz_index(j);
    if (kz == -n_z / 2) continue;  // Nyquist row
    for (int i = 0; i < n_x / 2; ++i) {  // column n_x/2 is the Nyquist column
      if (i == 0 && kz == 0) continue;
      const std::size_t m = static_cast<std::size_t>(j) * t.columns + i;
      const double k = std::hypot(wavenumber(i, p.patch_x_m), wavenumber(kz, p.patch_z_m));
      const std::complex<double> a = initial_amplitude(p, spectrum, i, kz);
      const std::complex<double> b = std::conj(initial_amplitude(p, spectrum, -i, -kz));
      t.omega[m] = angular_frequency(k, p.gravity_mps2, p.depth_m);
      t.sum_re[m] = static_cast<float>(a.real() + b.real());
      t.sum_im[m] = static_cast<float>(a.imag() + b.imag());
      t.diff_re[m] = static_cast<float>(a.real() - b.real());
      t.diff_im[m] = static_cast<float>(a.imag() - b.imag());
    }
  }
  return t;
}

}  // namespace ocean::sim
