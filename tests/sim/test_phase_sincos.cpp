// The sim's per-tick phase evaluation against the C library.
#include "phase_sincos.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace ocean::sim;
using std::numbers::pi;

TEST_CASE("phase_sincos matches sin and cos to float accuracy for any phase", "[sim][phase]") {
  double max_err = 0.0;
  for (int i = -200000; i <= 200000; ++i) {
    const double phase = i * 0.0137;
    const SinCos e = phase_sincos(phase);
    max_err = std::max({max_err, std::fabs(e.sin - std::sin(phase)), std::fabs(e.cos - std::cos(phase))});
  }
  CHECK(max_err < 2e-7);
  // Far out, the double phase itself is only known to its last bit (|phase| * 1.1e-16); the
  // reduction may lose a little more than that, but not float accuracy.
  for (double phase : {1e6 + 0.1, 3.3e8, -7.7e9, 1.234e11}) {
    const SinCos e = phase_sincos(phase);
    const double err = std::max(std::fabs(e.sin - std::sin(phase)), std::fabs(e.cos - std::cos(phase)));
    CHECK(err < 2e-7 + std::fabs(phase) * 1e-17);
  }
  for (int q = -8; q <= 8; ++q) {  // quadrant boundaries land exactly
    const SinCos e = phase_sincos(q * pi / 2);
    CHECK(std::fabs(e.sin - std::sin(q * pi / 2)) < 1e-7);
    CHECK(std::fabs(e.cos - std::cos(q * pi / 2)) < 1e-7);
  }
}
