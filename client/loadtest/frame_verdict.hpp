// The two judgements made on every frame a simulated client reconstructs: is it within the
// profile's quantization bound of the ground truth, and did it arrive before its render time.
#pragma once

#include "common/channels.hpp"
#include "tick.hpp"

#include <cstdint>
#include <span>

namespace ocean::loadtest {

// Slack for the truth being recomputed in another process (FFT rounding, a few float ulps):
// 1e-5 m is 0.1% of the finest height step. Not a loosening of the bound: the codec's own bound
// holds against the server's floats, which can differ from ours in the last bits. The same slack
// serves every channel (displacement in metres, slopes and derivatives dimensionless).
inline constexpr double kTruthSlack = 1e-5;

// The streamed channels of a frame (common/channels.hpp), empty where it carries none. The
// Jacobian is not among them: the decoder computes it from the derivatives, so checking those
// checks what it is made of.
using FrameChannels = PerChannel<std::span<const float>>;

// codec::ReconstructedFrame and sim::Frame list their channels' members beside them
// (channel_members, found by argument-dependent lookup); this header needs neither.
template <typename Frame>
FrameChannels channels_of(const Frame& f) {
  FrameChannels out;
  const auto& members = channel_members(&f);
  for (int ch = 0; ch < kChannelCount; ++ch) out[ch] = f.*members[ch];
  return out;
}

// The report's figures: each the worst of its channels (figure_of), the bound its step's half.
enum class ErrorFigure { height, slope, disp, disp_deriv };
constexpr ErrorFigure figure_of(const ChannelInfo& c) {
  if (c.group == ChannelGroup::always) return ErrorFigure::height;
  if (c.group == ChannelGroup::normals) return ErrorFigure::slope;
  return c.unit == ChannelUnit::displacement ? ErrorFigure::disp : ErrorFigure::disp_deriv;
}

// Per figure: a frame's error (max |reconstructed - truth| over the figure's channels), or its
// bound (the channels' step / 2; 0 leaves them unchecked: the stream does not carry them).
struct ErrorFigures {
  double height_m = 0.0;    // the heights
  double slope = 0.0;       // the normals' channels (both slopes)
  double disp_m = 0.0;      // the choppy channels in metres (both displacements)
  double disp_deriv = 0.0;  // the other choppy channels (the three displacement derivatives)
  double& operator[](ErrorFigure f);
};
using FrameError = ErrorFigures;
using ErrorBounds = ErrorFigures;

// The bounds of a stream (a Profile, codec::StreamConfig or the Welcome's StreamParams).
template <typename Stream>
ErrorBounds bounds_of(const Stream& s) {
  ErrorBounds b;
  for (const ChannelInfo& c : kChannels)
    if (carried(c, s.normals, s.choppy)) b[figure_of(c)] = step_of(s, c.unit) / 2.0;
  return b;
}

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
