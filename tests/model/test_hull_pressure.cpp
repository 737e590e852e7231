// HullPressure against its formula summed mode by mode here, in both arithmetics (the sim's Libm
// walks the phases as powers, the codec's Det computes each directly), with more hulls and
// headings than it keeps envelopes for.
#include "arithmetic.hpp"
#include "hull_pressure.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

using namespace ocean::model;

namespace {

using std::numbers::pi;

// The coefficient at lattice mode (row r, column c) of the Gaussian hull at `pose`, as the
// header writes it.
std::complex<double> expected(const HullPose& pose, int n, double size_m, int r, int c) {
  const auto bin = [n](int i) { return i < n / 2 ? i : i - n; };
  const double kx = 2.0 * pi * bin(c) / size_m, kz = 2.0 * pi * bin(r) / size_m;
  const double sa = pose.hull.length_m / 4.0, sc = pose.hull.beam_m / 4.0;
  const double ka = kx * pose.dir_x + kz * pose.dir_z, kc = kz * pose.dir_x - kx * pose.dir_z;
  const double amplitude = pose.hull.draft_m * 2.0 * pi * sa * sc / (size_m * size_m) *
                           std::exp(-(sa * sa * ka * ka + sc * sc * kc * kc) / 2.0);
  return amplitude * std::polar(1.0, -(kx * pose.x_m + kz * pose.z_m));
}

std::vector<HullPose> fleet(int count, double turn) {
  std::vector<HullPose> poses;
  for (int i = 0; i < count; ++i) {
    const double heading = turn + 0.37 * i;
    poses.push_back(HullPose{Hull{8.0 + i, 2.5 + 0.1 * i, 0.5 + 0.05 * i}, 17.3 + 29.1 * i, 491.7 - 13.9 * i,
                             std::cos(heading), std::sin(heading)});
  }
  return poses;
}

template <class Math>
double worst_error(HullPressure<Math>& pressure, const std::vector<HullPose>& poses, int n, double size_m,
                   double scale) {
  const int columns = n / 2 + 1;
  std::vector<std::complex<double>> out(static_cast<std::size_t>(n) * columns);
  pressure.add(poses, scale, out.data());
  double worst = 0.0, peak = 0.0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < columns; ++c) {
      std::complex<double> sum;
      for (const HullPose& p : poses) sum += scale * expected(p, n, size_m, r, c);
      peak = std::max(peak, std::abs(sum));
      worst = std::max(worst, std::abs(out[static_cast<std::size_t>(r) * columns + c] - sum));
    }
  return worst / peak;
}

}  // namespace

TEMPLATE_TEST_CASE("hull pressure is its Gaussian's Fourier coefficients in both arithmetics", "[model][wake]", Libm,
                   Det) {
  for (const int n : {16, 64, 128}) {
    const double size_m = 512.0;
    HullPressure<TestType> pressure(n, size_m);
    // 24 headings a call for four calls: 96 envelopes through a cache that keeps 64, so later
    // calls make new ones while an earlier hull of the same call still needs its own.
    for (int call = 0; call < 4; ++call) {
      INFO("n " << n << " call " << call);
      CHECK(worst_error(pressure, fleet(24, 0.11 * call), n, size_m, call % 2 ? -0.5 : 1.0) < 1e-12);
    }
    // The first call's hulls again, after their envelopes were dropped.
    CHECK(worst_error(pressure, fleet(24, 0.0), n, size_m, 1.0) < 1e-12);
  }
}

TEST_CASE("hulls added in one call sum exactly as hulls added one by one", "[model][wake]") {
  const int n = 64, columns = n / 2 + 1;
  HullPressure<Det> together(n, 300.0), apart(n, 300.0);
  const std::vector<HullPose> poses = fleet(HullPressure<Det>::kMaxHulls, 1.0);
  std::vector<std::complex<double>> a(static_cast<std::size_t>(n) * columns), b(a.size());
  together.add(poses, 0.75, a.data());
  for (const HullPose& p : poses) apart.add(std::span<const HullPose>(&p, 1), 0.75, b.data());
  CHECK(a == b);
  std::vector<HullPose> too_many = poses;
  too_many.push_back(poses.front());
  CHECK_THROWS_AS(together.add(too_many, 1.0, a.data()), std::invalid_argument);
}
