// SyntheticOcean: a reference height field for codec tests - a few hundred random grid modes,
// each a travelling cosine with w^2 = g k (tanh(k D) with depth), plus exact analytic slopes.
// Band-limited like the sim's frames (no DC, no Nyquist), independent of the sim library.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace ocean::codec::test {

struct SyntheticFrame {
  std::vector<float> height, slope_x, slope_z;
};

class SyntheticOcean {
 public:
  SyntheticOcean(int n, double patch_m, int modes, std::uint64_t seed, double rms_m = 0.3, double depth_m = 0.0,
                 double gravity = 9.81)
      : n_(n), patch_(patch_m) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> idx(-n / 2 + 1, n / 2 - 1);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double two_pi = 6.283185307179586;
    double energy = 0.0;
    for (int j = 0; j < modes; ++j) {
      Mode m;
      do {
        m.mx = idx(rng);
        m.mz = idx(rng);
      } while (m.mx == 0 && m.mz == 0);
      m.kx = two_pi * m.mx / patch_m;
      m.kz = two_pi * m.mz / patch_m;
      const double k = std::hypot(m.kx, m.kz);
      m.w = std::sqrt(gravity * k * (depth_m > 0 ? std::tanh(k * depth_m) : 1.0));
      m.amp = std::pow(k, -1.5) * (0.2 + u01(rng));  // steep like an ocean spectrum
      m.phase = two_pi * u01(rng);
      energy += 0.5 * m.amp * m.amp;
      modes_.push_back(m);
    }
    const double scale = rms_m / std::sqrt(energy);
    for (Mode& m : modes_) m.amp *= scale;
  }

  int n() const { return n_; }

  SyntheticFrame at(double t) const {
    const int n = n_;
    const double dx = patch_ / n;
    std::vector<double> h(n * n, 0.0), sx(n * n, 0.0), sz(n * n, 0.0);
    std::vector<double> ca(n), sa(n), cb(n), sb(n);
    for (const Mode& m : modes_) {
      for (int i = 0; i < n; ++i) {
        ca[i] = std::cos(m.kx * i * dx);
        sa[i] = std::sin(m.kx * i * dx);
        const double b = m.kz * i * dx - m.w * t + m.phase;
        cb[i] = std::cos(b);
        sb[i] = std::sin(b);
      }
      for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
          const double c = ca[x] * cb[z] - sa[x] * sb[z];  // cos(a + b)
          const double s = sa[x] * cb[z] + ca[x] * sb[z];  // sin(a + b)
          h[z * n + x] += m.amp * c;
          sx[z * n + x] -= m.amp * m.kx * s;
          sz[z * n + x] -= m.amp * m.kz * s;
        }
    }
    SyntheticFrame f;
    f.height.assign(h.begin(), h.end());
    f.slope_x.assign(sx.begin(), sx.end());
    f.slope_z.assign(sz.begin(), sz.end());
    return f;
  }

 private:
  struct Mode {
    int mx, mz;
    double kx, kz, w, amp, phase;
  };
  int n_;
  double patch_;
  std::vector<Mode> modes_;
};

}  // namespace ocean::codec::test
