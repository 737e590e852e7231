// phase_sincos(): sin and cos of a phase w t given in double, cheap enough for every mode of every
// tick. The phase is reduced modulo pi/2 in double (so the result depends only on the phase, never
// on earlier ticks), then two float polynomials on [-pi/4, pi/4] give about 1e-7 absolute accuracy.
// Written without branches, selects or library calls so the per-mode loop vectorises.
#pragma once

namespace ocean::sim {

struct SinCos {
  float sin;
  float cos;
};

// Valid for |phase| < 2^50; callers bound w t far below that.
inline SinCos phase_sincos(double phase) {
  constexpr double round_magic = 0x1.8p52;  // adding and subtracting rounds to the nearest integer
  constexpr double two_over_pi = 0.63661977236758134308;
  // pi/2 split Cody-Waite style: the high part has 33 significant bits, so q * high is exact.
  constexpr double half_pi_high = 1.57079632673412561417e+00;
  constexpr double half_pi_low = 6.07710050650619224932e-11;
  const double q = (phase * two_over_pi + round_magic) - round_magic;
  const double r = (phase - q * half_pi_high) - q * half_pi_low;
  const double quadrant = q - 4.0 * ((q * 0.25 + round_magic) - round_magic);  // -2, -1, 0, 1 or 2

  const float x = static_cast<float>(r);
  const float x2 = x * x;
  // Minimax coefficients for |x| <= pi/4 (as in Cephes sinf/cosf).
  const float s = x + x * x2 * (-1.6666654611e-1f + x2 * (8.3321608736e-3f + x2 * -1.9515295891e-4f));
  const float c = 1.0f - 0.5f * x2 +
                  x2 * x2 * (4.166664568298827e-2f + x2 * (-1.388731625493765e-3f + x2 * 2.443315711809948e-5f));

  // Rotate (s, c) by quadrant * pi/2 with (a, b) = (cos, sin)(quadrant * pi/2), written as exact
  // integer polynomials in the quadrant so the loop needs no selects: a, b are exactly -1, 0 or 1.
  const float qf = static_cast<float>(quadrant);
  const float q2 = qf * qf;
  const float a = (6.0f - 7.0f * q2 + q2 * q2) / 6.0f;
  const float b = qf * (4.0f - q2) / 3.0f;
  return {a * s + b * c, a * c - b * s};
}

}  // namespace ocean::sim
