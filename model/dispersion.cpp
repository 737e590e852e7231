// Dispersion relation and group velocity, finite and infinite depth.
#include "dispersion.hpp"

#include "arithmetic.hpp"

#include <cmath>

namespace ocean::model {
namespace {

// Beyond k D = 20, tanh(k D) is 1 to double precision and the finite-depth formulas would only
// produce inf * 0; the deep-water forms are then exact.
constexpr double deep_kd = 20.0;

}  // namespace

template <class Math>
double angular_frequency(double k, double gravity, double depth_m) {
  if (!(k > 0.0)) return 0.0;
  const double kd = k * depth_m;
  if (kd > deep_kd) return std::sqrt(gravity * k);
  return std::sqrt(gravity * k * Math::tanh(kd));
}

template <class Math>
double group_velocity(double k, double gravity, double depth_m) {
  if (k <= 0.0) return std::isinf(depth_m) ? INFINITY : std::sqrt(gravity * depth_m);  // shallow-water limit
  const double w = angular_frequency<Math>(k, gravity, depth_m);
  const double kd = k * depth_m;
  if (kd > deep_kd) return 0.5 * w / k;
  const double sech = 1.0 / Math::cosh(kd);
  // d/dk (g k tanh(kD)) = g (tanh(kD) + kD sech^2(kD)) = 2 w dw/dk
  return gravity * (Math::tanh(kd) + kd * sech * sech) / (2.0 * w);
}

template double angular_frequency<Libm>(double, double, double);
template double angular_frequency<Det>(double, double, double);
template double group_velocity<Libm>(double, double, double);
template double group_velocity<Det>(double, double, double);

}  // namespace ocean::model
