// det_math agrees with the C library to near one ulp over the ranges the codec uses.
#include "det_math.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace ocean::codec;

TEST_CASE("det_cos and det_sin match std within 2e-15 over several turns") {
  double worst = 0.0;
  for (int i = -20000; i <= 20000; ++i) {
    const double x = i * 0.0013;
    worst = std::max(worst, std::fabs(det_cos(x) - std::cos(x)));
    worst = std::max(worst, std::fabs(det_sin(x) - std::sin(x)));
  }
  CHECK(worst < 2e-15);
}

TEST_CASE("det_tanh and det_exp_neg match std") {
  for (double x = 0.0; x < 30.0; x += 0.01) {
    CHECK(std::fabs(det_tanh(x) - std::tanh(x)) < 1e-15);
    CHECK(std::fabs(det_exp_neg(x) - std::exp(-x)) <= 5e-14 * std::exp(-x));  // squaring doubles relative error
  }
}

TEST_CASE("det_angular_frequency follows the dispersion relation") {
  CHECK(det_angular_frequency(0.0, 9.81, 0.0) == 0.0);
  CHECK(std::fabs(det_angular_frequency(0.1, 9.81, 0.0) - std::sqrt(0.981)) < 1e-15);
  CHECK(std::fabs(det_angular_frequency(0.1, 9.81, 5.0) - std::sqrt(0.981 * std::tanh(0.5))) < 1e-15);
}

TEST_CASE("to_fixed rounds to nearest") {
  CHECK(to_fixed(1.5, 0) == 2);
  CHECK(to_fixed(-1.5, 0) == -1);
  CHECK(to_fixed(0.25, 2) == 1);
  CHECK(to_fixed(-0.75, 30) == -(std::int64_t{3} << 28));
}
