// HullPressure: the Fourier coefficients of the pressure hulls lay on the water (as p / (rho g),
// metres), on a square lattice of the world of side `size_m` with n x (n/2 + 1) modes (rows kz in
// FFT order, columns kx >= 0). A hull is a Gaussian: draft exp(-along^2 / (2 sa^2) - across^2 /
// (2 sc^2)), sa = length / 4, sc = beam / 4, whose coefficient at k is exactly (Poisson's sum over
// the lattice's periodic images)
//   draft 2 pi sa sc / size^2 exp(-(sa^2 ka^2 + sc^2 kc^2) / 2) e^{-i k.x}
// with ka, kc the wavevector along and across the hull. The sim forces its wake with it and the
// codec predicts the same forcing (CODEC.md 7.9), each in its own arithmetic (arithmetic.hpp).
// Pure; the envelope of each hull and heading is kept, so a straight leg costs a complex product
// per mode a step.
#pragma once

#include "arithmetic.hpp"
#include "vessel_track.hpp"

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace ocean::model {

template <class Math>
class HullPressure {
 public:
  HullPressure(int n, double size_m);

  // Adds the hulls at `poses` (x, z measured from the lattice's corner) times `scale` to `out`
  // (n (n/2 + 1) coefficients), each mode summing them in their order. At most kMaxHulls.
  void add(std::span<const HullPose> poses, double scale, std::complex<double>* out);

  static constexpr std::size_t kMaxHulls = 32;

  int n() const { return n_; }

 private:
  struct Envelope {
    bool fits(const HullPose& pose) const;
    Hull hull;
    double dir_x, dir_z;
    std::vector<double> value;  // per mode
  };
  // The sim's phases of a row or column (hull_pressure.cpp); `rows` null for the columns.
  void power_phases(double step, double scale, double* column_re, double* column_im, std::complex<double>* rows) const;
  // The envelope of this pose's hull and heading, made if new; it never drops one `in_use` needs.
  const double* envelope(const HullPose& pose, std::span<const HullPose> in_use);

  int n_, columns_;
  double size_m_;
  std::vector<Envelope> envelopes_;  // the last few hulls and headings
  // Per hull of the current call: its row phases, column phases and envelope.
  std::vector<std::complex<double>> row_phase_;
  std::vector<double> column_re_, column_im_;
  std::vector<const double*> envelope_of_;
};

extern template class HullPressure<Libm>;
extern template class HullPressure<Det>;

}  // namespace ocean::model
