#include "frame_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocean::loadtest {
namespace {

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

double& ErrorFigures::operator[](ErrorFigure f) {
  switch (f) {
    case ErrorFigure::height: return height_m;
    case ErrorFigure::slope: return slope;
    case ErrorFigure::disp: return disp_m;
    case ErrorFigure::disp_deriv: return disp_deriv;
  }
  return height_m;
}

FrameError frame_error(const FrameChannels& got, const FrameChannels& truth) {
  FrameError e;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    double& worst = e[figure_of(kChannels[ch])];
    worst = std::max(worst, max_abs_error(got[ch], truth[ch]));
  }
  return e;
}

FrameError frame_error(std::span<const float> height, std::span<const float> slope_x, std::span<const float> slope_z,
                       std::span<const float> truth_height, std::span<const float> truth_slope_x,
                       std::span<const float> truth_slope_z) {
  FrameChannels got, truth;
  got[ChannelId::height] = height;
  got[ChannelId::slope_x] = slope_x;
  got[ChannelId::slope_z] = slope_z;
  truth[ChannelId::height] = truth_height;
  truth[ChannelId::slope_x] = truth_slope_x;
  truth[ChannelId::slope_z] = truth_slope_z;
  return frame_error(got, truth);
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
