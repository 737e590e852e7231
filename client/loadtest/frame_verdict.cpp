#include "frame_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocean::loadtest {
namespace {

// The worst of several channels judged against one bound.
double worst_of(std::initializer_list<double> errors) { return std::max(errors); }

// Checked only when the stream carries the channel; NaN never passes.
bool channel_within(double error, double bound) { return bound <= 0.0 || error <= bound + kTruthSlack; }

}  // namespace

double max_abs_error(std::span<const float> got, std::span<const float> truth) {
  if (got.size() != truth.size()) return std::numeric_limits<double>::infinity();
  float worst = 0.0f;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const float d = std::fabs(got[i] - truth[i]);
    worst = d > worst || std::isnan(d) ? d : worst;
  }
  return std::isnan(worst) ? std::numeric_limits<double>::infinity() : static_cast<double>(worst);
}

FrameError frame_error(const FrameChannels& got, const FrameChannels& truth) {
  FrameError e;
  e.height_m = max_abs_error(got.height, truth.height);
  e.slope = worst_of({max_abs_error(got.slope_x, truth.slope_x), max_abs_error(got.slope_z, truth.slope_z)});
  e.disp_m = worst_of({max_abs_error(got.disp_x, truth.disp_x), max_abs_error(got.disp_z, truth.disp_z)});
  e.disp_deriv = worst_of({max_abs_error(got.disp_xx, truth.disp_xx), max_abs_error(got.disp_zz, truth.disp_zz),
                           max_abs_error(got.disp_xz, truth.disp_xz)});
  return e;
}

FrameError frame_error(std::span<const float> height, std::span<const float> slope_x, std::span<const float> slope_z,
                       std::span<const float> truth_height, std::span<const float> truth_slope_x,
                       std::span<const float> truth_slope_z) {
  return frame_error(FrameChannels{.height = height, .slope_x = slope_x, .slope_z = slope_z},
                     FrameChannels{.height = truth_height, .slope_x = truth_slope_x, .slope_z = truth_slope_z});
}

bool within_bounds(const FrameError& error, const ErrorBounds& bounds) {
  if (!(error.height_m <= bounds.height_m + kTruthSlack)) return false;
  return channel_within(error.slope, bounds.slope) && channel_within(error.disp_m, bounds.disp_m) &&
         channel_within(error.disp_deriv, bounds.disp_deriv);
}

bool arrived_on_time(double arrival_s, Tick tick, double clock_offset_s, double tick_period_s,
                     double interpolation_delay_s) {
  const double render_time = clock_offset_s + static_cast<double>(tick) * tick_period_s + interpolation_delay_s;
  return arrival_s <= render_time;
}

}  // namespace ocean::loadtest
