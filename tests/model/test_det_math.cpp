// det_math agrees with the C library to near one ulp over the ranges the codec uses.
#include "arithmetic.hpp"
#include "det_math.hpp"
#include "dispersion.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ocean::model;

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

TEST_CASE("The dispersion relation in the Det arithmetic") {
  const double deep = INFINITY;
  CHECK(angular_frequency<Det>(0.0, 9.81, deep) == 0.0);
  CHECK(std::fabs(angular_frequency<Det>(0.1, 9.81, deep) - std::sqrt(0.981)) < 1e-15);
  CHECK(std::fabs(angular_frequency<Det>(0.1, 9.81, 5.0) - std::sqrt(0.981 * std::tanh(0.5))) < 1e-15);
  // Deep water is exactly the k D > 20 limit, and both arithmetics take it alike.
  CHECK(angular_frequency<Det>(0.1, 9.81, 500.0) == angular_frequency<Libm>(0.1, 9.81, deep));
}

TEST_CASE("to_fixed rounds to nearest") {
  CHECK(to_fixed(1.5, 0) == 2);
  CHECK(to_fixed(-1.5, 0) == -1);
  CHECK(to_fixed(0.25, 2) == 1);
  CHECK(to_fixed(-0.75, 30) == -(std::int64_t{3} << 28));
}

namespace {

// Relative error against libm, measured over a set of arguments; returns the worst.
template <class Det, class Ref>
double worst_relative(const std::vector<double>& args, Det det, Ref ref) {
  double worst = 0.0;
  for (double x : args) {
    const double want = ref(x), got = det(x);
    const double err = want == got ? 0.0 : std::fabs(got - want) / std::fabs(want);
    worst = std::max(worst, err);
  }
  return worst;
}

std::vector<double> log_spaced(double lo, double hi, int count) {
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(lo * std::pow(hi / lo, (i + 0.5) / count));
  return v;
}

std::vector<double> lin_spaced(double lo, double hi, int count) {
  std::vector<double> v;
  for (int i = 0; i <= count; ++i) v.push_back(lo + (hi - lo) * i / count);
  return v;
}

}  // namespace

TEST_CASE("det_log matches log over the whole double range", "[det_math][scene_model]") {
  std::vector<double> xs = log_spaced(1e-300, 1e300, 200000);
  for (double d : lin_spaced(-1e-3, 1e-3, 20000)) xs.push_back(1.0 + d);  // ln x -> 0: relative precision
  for (double d : {1e-15, 1e-12, 1e-9, -1e-15, -1e-12}) xs.push_back(1.0 + d);
  xs.push_back(0x1.0p-1074);  // smallest subnormal
  xs.push_back(3e-310);
  const double worst = worst_relative(xs, det_log, [](double x) { return std::log(x); });
  INFO("worst relative error " << worst);
  CHECK(worst < 1e-15);
  CHECK(det_log(1.0) == 0.0);
  CHECK(det_log(0.0) == -INFINITY);
  CHECK(det_log(INFINITY) == INFINITY);
  CHECK(std::isnan(det_log(-1.0)));
}

TEST_CASE("det_exp matches exp, overflows to inf and underflows to 0", "[det_math][scene_model]") {
  const double worst = worst_relative(lin_spaced(-708.0, 709.7, 400000), det_exp, [](double x) { return std::exp(x); });
  INFO("worst relative error " << worst);
  CHECK(worst < 1e-15);
  const double tiny = worst_relative(lin_spaced(-1e-6, 1e-6, 2000), det_exp, [](double x) { return std::exp(x); });
  CHECK(tiny < 1e-15);
  CHECK(det_exp(0.0) == 1.0);
  CHECK(det_exp(710.0) == INFINITY);
  CHECK(det_exp(1e300) == INFINITY);
  CHECK(det_exp(-746.5) == 0.0);
  CHECK(det_exp(-INFINITY) == 0.0);
  CHECK(std::fabs(det_exp(-740.0) - std::exp(-740.0)) <= 0x1.0p-1074);  // subnormal: one rounding
}

TEST_CASE("det_pow matches pow for the spectrum's bases and exponents", "[det_math][scene_model]") {
  double worst = 0.0;
  for (double x : log_spaced(1e-12, 1e12, 3000))
    for (double y : {-2.5, -1.3, -0.22, 1.0 / 3.0, 1.3, 2.5, 4.06, 5.0, -4.7})
      worst = std::max(worst, std::fabs(det_pow(x, y) - std::pow(x, y)) / std::pow(x, y));
  for (double y : lin_spaced(0.0, 1.0, 1000))  // JONSWAP's peak enhancement 3.3^e
    worst = std::max(worst, std::fabs(det_pow(3.3, y) - std::pow(3.3, y)) / std::pow(3.3, y));
  for (double y : lin_spaced(-1.0, 1.0, 1000))  // Donelan-Banner's 10^epsilon
    worst = std::max(worst, std::fabs(det_pow(10.0, y) - std::pow(10.0, y)) / std::pow(10.0, y));
  INFO("worst relative error " << worst);
  CHECK(worst < 1e-13);  // grows like |y ln x| 2^-52: here |y ln x| reaches 138
  double cbrt_worst = 0.0;
  for (double x : log_spaced(1e-20, 1e20, 20000))
    cbrt_worst = std::max(cbrt_worst, std::fabs(det_pow(x, 1.0 / 3.0) - std::cbrt(x)) / std::cbrt(x));
  INFO("cbrt as pow(x, 1/3): worst relative error " << cbrt_worst);
  CHECK(cbrt_worst < 1e-14);
  CHECK(det_pow(1.0, 123.0) == 1.0);
}

TEST_CASE("det_atan2 matches atan2 in every quadrant", "[det_math][scene_model]") {
  double worst = 0.0;
  for (double mag : {1e-300, 1e-20, 1e-3, 1.0, 7.5, 1e5, 1e300})
    for (int i = 0; i < 4000; ++i) {
      const double angle = -3.14159 + 6.28318 * (i + 0.5) / 4000;
      const double y = mag * std::sin(angle), x = mag * std::cos(angle);
      const double want = std::atan2(y, x);
      worst = std::max(worst, std::fabs(det_atan2(y, x) - want) / std::fabs(want));
    }
  for (double ratio : log_spaced(1e-300, 1e300, 4000))
    for (double sx : {1.0, -1.0})
      for (double sy : {1.0, -1.0}) {
        const double want = std::atan2(sy * ratio, sx);
        worst = std::max(worst, std::fabs(det_atan2(sy * ratio, sx) - want) / std::fabs(want));
      }
  INFO("worst relative error " << worst);
  CHECK(worst < 1e-15);
  CHECK(det_atan2(0.0, 1.0) == 0.0);
  CHECK(det_atan2(0.0, -1.0) == kPi);
  CHECK(det_atan2(1.0, 0.0) == std::atan2(1.0, 0.0));
  CHECK(det_atan2(-1.0, 0.0) == std::atan2(-1.0, 0.0));
  CHECK(det_atan2(0.0, 0.0) == 0.0);
}

TEST_CASE("det_log_gamma matches lgamma", "[det_math][scene_model]") {
  std::vector<double> xs = log_spaced(1e-300, 1e300, 20000);
  for (double x : lin_spaced(0.01, 40.0, 40000)) xs.push_back(x);
  for (double x : lin_spaced(1e5, 2e5, 1000)) xs.push_back(x + 0.5);  // the cos-2s s + 1/2 of light winds
  double worst = 0.0;
  for (double x : xs) {
    int sign = 0;
    const double want = ::lgamma_r(x, &sign);
    worst = std::max(worst, std::fabs(det_log_gamma(x) - want) / std::max(1.0, std::fabs(want)));
  }
  INFO("worst error relative to max(1, |lgamma|) " << worst);
  CHECK(worst < 1e-13);  // a few ulp of ln Gamma(16) = 27.9, from which small x subtract
  CHECK(det_log_gamma(1.0) == Approx(0.0).margin(1e-14));
  CHECK(det_log_gamma(2.0) == Approx(0.0).margin(1e-14));
}

TEST_CASE("det_cosh matches cosh", "[det_math][scene_model]") {
  const double worst = worst_relative(lin_spaced(-709.0, 709.0, 200000), det_cosh, [](double x) { return std::cosh(x); });
  INFO("worst relative error " << worst);
  CHECK(worst < 1e-15);
  CHECK(det_cosh(0.0) == 1.0);
  CHECK(det_cosh(800.0) == INFINITY);
}

TEST_CASE("det_cos_sin equals det_cos and det_sin bit for bit", "[det_math][scene_model]") {
  std::vector<double> xs;
  for (int i = 0; i < 1000; ++i) xs.push_back((i - 500) * 0.0137);
  for (int i = 0; i < 1000; ++i) xs.push_back(1e3 + i * 3.3e6);  // phases of long uptimes, up to 3.3e9
  for (std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{15}, std::size_t{16}, std::size_t{17}, xs.size()}) {
    std::vector<double> c(count + 1, -7.0), s(count + 1, -7.0);
    det_cos_sin(xs.data(), count, c.data(), s.data());
    for (std::size_t i = 0; i < count; ++i) {
      REQUIRE(c[i] == det_cos(xs[i]));
      REQUIRE(s[i] == det_sin(xs[i]));
    }
    CHECK(c[count] == -7.0);  // nothing written past the end
    CHECK(s[count] == -7.0);
  }
}

TEST_CASE("det_wrap_angle is the exact remainder by 2 pi", "[det_math][scene_model]") {
  for (double x : {0.0, 1.0, -1.0, 3.0, -3.0, 3.2, -3.2, 7.0, -100.5, 17453.29, -17453.29, 1e9, kPi, -kPi, 3 * kPi})
    CHECK(std::fabs(det_wrap_angle(x)) == std::fabs(std::remainder(x, kTwoPi)));
  for (int i = -5000; i <= 5000; ++i) {
    const double x = i * 0.01234567;
    REQUIRE(det_wrap_angle(x) == std::remainder(x, kTwoPi));
  }
}

TEST_CASE("det_ functions reproduce the test vectors of CODEC.md 12.1 bit for bit", "[det_math][scene_model]") {
  CHECK(det_log(10.0) == 0x1.26bb1bbb55516p+1);
  CHECK(det_log(0.3) == -0x1.34378fcbda721p+0);
  CHECK(det_exp(-1.5) == 0x1.c8f87724b5c1dp-3);
  CHECK(det_exp(700.5) == 0x1.8625c7d4f56c2p+1010);
  CHECK(det_pow(3.3, 0.7) == 0x1.273c7cfb01256p+1);
  CHECK(det_pow(0.49, -2.5) == 0x1.7ccb3107ef8ccp+2);
  CHECK(det_atan2(1.0, -2.0) == 0x1.56c6e7397f5aep+1);
  CHECK(det_atan2(-3.0, 0.5) == -0x1.67d8863bc99bcp+0);
  CHECK(det_log_gamma(0.3) == 0x1.188637a6c41bp+0);
  CHECK(det_log_gamma(150000.5) == 0x1.8fd7f8141209ap+20);
  CHECK(det_cosh(2.5) == 0x1.88776e4b30aa3p+2);
  CHECK(det_wrap_angle(100.0) == -0x1.0fdaa22168cp-1);
  CHECK(det_cos(2e9) == 0x1.9dcefc534b5a6p-2);
  CHECK(det_sin(2e9) == 0x1.d454ed4068727p-1);
}
