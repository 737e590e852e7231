// The two judgements made on every frame a simulated client reconstructs: is it within the
// profile's quantization bound of the ground truth, and did it arrive before its render time.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <span>

namespace ocean::loadtest {

// Slack for the truth being recomputed in another process (FFT rounding, a few float ulps):
// 1e-5 m is 0.1% of the finest height step. Not a loosening of the bound: the codec's own bound
// holds against the server's floats, which can differ from ours in the last bits.
inline constexpr double kTruthSlack = 1e-5;

struct FrameError {
  double height_m = 0.0;  // max |reconstructed - truth| over the heights
  double slope = 0.0;     // over both slope channels (0 when the frame carries none)
};

struct ErrorBounds {
  double height_m;  // height_step / 2
  double slope;     // slope_step / 2 (0: slopes not checked)
};

// Max absolute differences; a size mismatch counts as infinitely wrong.
double max_abs_error(std::span<const float> got, std::span<const float> truth);
FrameError frame_error(std::span<const float> height, std::span<const float> slope_x, std::span<const float> slope_z,
                       std::span<const float> truth_height, std::span<const float> truth_slope_x,
                       std::span<const float> truth_slope_z);
bool within_bounds(const FrameError& error, const ErrorBounds& bounds);

// On time when the frame arrived by its render time: the client's estimate of when tick 0 arrives
// (ArrivalClock offset: server clock plus the fastest one-way delay), plus tick * period, plus
// the interpolation delay the renderer stays behind.
bool arrived_on_time(double arrival_s, Tick tick, double clock_offset_s, double tick_period_s,
                     double interpolation_delay_s);

}  // namespace ocean::loadtest
