#include "frame_verdict.hpp"

#include <cmath>
#include <limits>

namespace ocean::loadtest {

double max_abs_error(std::span<const float> got, std::span<const float> truth) {
  if (got.size() != truth.size()) return std::numeric_limits<double>::infinity();
  float worst = 0.0f;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const float d = std::fabs(got[i] - truth[i]);
    worst = d > worst || std::isnan(d) ? d : worst;
  }
  return std::isnan(worst) ? std::numeric_limits<double>::infinity() : static_cast<double>(worst);
}

FrameError frame_error(std::span<const float> height, std::span<const float> slope_x, std::span<const float> slope_z,
                       std::span<const float> truth_height, std::span<const float> truth_slope_x,
                       std::span<const float> truth_slope_z) {
  FrameError e;
  e.height_m = max_abs_error(height, truth_height);
  if (!slope_x.empty() || !slope_z.empty())
    e.slope = std::max(max_abs_error(slope_x, truth_slope_x), max_abs_error(slope_z, truth_slope_z));
  return e;
}

bool within_bounds(const FrameError& error, const ErrorBounds& bounds) {
  if (!(error.height_m <= bounds.height_m + kTruthSlack)) return false;
  return bounds.slope <= 0.0 || error.slope <= bounds.slope + kTruthSlack;
}

bool arrived_on_time(double arrival_s, Tick tick, double clock_offset_s, double tick_period_s,
                     double interpolation_delay_s) {
  const double render_time = clock_offset_s + static_cast<double>(tick) * tick_period_s + interpolation_delay_s;
  return arrival_s <= render_time;
}

}  // namespace ocean::loadtest
