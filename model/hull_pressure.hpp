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
#include <vector>

namespace ocean::model {

template <class Math>
class HullPressure {
 public:
  HullPressure(int n, double size_m);

  // Adds the hull at `pose` (x, z measured from the lattice's corner) times `scale` to `out`
  // (n (n/2 + 1) coefficients).
  void add(const HullPose& pose, double scale, std::complex<double>* out);

  int n() const { return n_; }

 private:
  struct Envelope {
    Hull hull;
    double dir_x, dir_z;
    std::vector<double> value;  // per mode
  };
  const std::vector<double>& envelope(const HullPose& pose);

  int n_, columns_;
  double size_m_;
  std::vector<Envelope> envelopes_;  // the last few hulls and headings
  std::vector<std::complex<double>> row_phase_, column_phase_;
};

extern template class HullPressure<Libm>;
extern template class HullPressure<Det>;

}  // namespace ocean::model
