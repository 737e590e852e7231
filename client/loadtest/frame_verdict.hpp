// The two judgements made on every frame a simulated client reconstructs: is it within the
// profile's quantization bound of the ground truth, and did it arrive before its render time.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <span>

namespace ocean::loadtest {

// Slack for the truth being recomputed in another process (FFT rounding, a few float ulps):
// 1e-5 m is 0.1% of the finest height step. Not a loosening of the bound: the codec's own bound
// holds against the server's floats, which can differ from ours in the last bits. The same slack
// serves every channel (displacement in metres, slopes and derivatives dimensionless).
inline constexpr double kTruthSlack = 1e-5;

// The streamed channels of a frame, empty where it carries none. The Jacobian is not among them:
// the decoder computes it from the derivatives, so checking those checks what it is made of.
struct FrameChannels {
  std::span<const float> height{}, slope_x{}, slope_z{};
  std::span<const float> disp_x{}, disp_z{}, disp_xx{}, disp_zz{}, disp_xz{};  // choppy streams
};

// codec::ReconstructedFrame and sim::Frame name their channels alike; this header needs neither.
template <typename Frame>
FrameChannels channels_of(const Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz};
}

struct FrameError {
  double height_m = 0.0;    // max |reconstructed - truth| over the heights
  double slope = 0.0;       // over both slope channels
  double disp_m = 0.0;      // over both displacement channels
  double disp_deriv = 0.0;  // over the three displacement derivatives
};

// A bound of 0 leaves its channel unchecked: the stream does not carry it.
struct ErrorBounds {
  double height_m;          // height_step / 2
  double slope;             // slope_step / 2 (normals)
  double disp_m = 0.0;      // disp_step_m / 2 (choppy)
  double disp_deriv = 0.0;  // slope_step / 2 (choppy)
};

// Max absolute differences; a size mismatch counts as infinitely wrong.
double max_abs_error(std::span<const float> got, std::span<const float> truth);
// Channel by channel: one carried by one side only is a size mismatch (a choppy stream's frame
// without its displacement is wrong), both empty is no error.
FrameError frame_error(const FrameChannels& got, const FrameChannels& truth);
// Heights and slopes only (a stream without choppy channels), by the same rule.
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
