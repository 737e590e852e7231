// ReceiveRate: how one client's downlink rate varied, from its cumulative received byte count
// sampled about every 100 ms (the load test's loop samples every client).
//  - peak: the most bytes in any 1 s window (the run of samples spanning at most 1 s, so a late
//    sample never stretches one). Windows that start at or after the client's first frame give
//    its steady peak, the others (the connection's own start: handshake and first keyframe) its
//    startup peak, so one does not hide the other.
//  - calm: the median rate of its whole 1 s windows from the first frame on, the stream's rate
//    between bursts: a keyframe or a SceneUpdate lifts only the windows it arrives in.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace ocean::loadtest {

class ReceiveRate {
 public:
  static constexpr double kWindowS = 1.0;
  static constexpr double kSlackS = 0.02;  // sampling jitter tolerated in a window's span

  // `bytes` received by steady time t_s (cumulative, never decreasing; t_s increasing).
  void sample(double t_s, std::uint64_t bytes);
  // When the first frame arrived; windows and intervals starting from then on are steady ones.
  void set_first_frame(double t_s) {
    if (!first_frame_s_) first_frame_s_ = t_s;
  }

  // kbit/s over the busiest window: bytes in it * 8 / 1000 per 1 s (a window shorter than 1 s,
  // at the very start, counts its bytes as if the rest of the second held none).
  double peak_kbps() const { return peak_bytes_ * 8.0 / 1000.0; }
  double startup_peak_kbps() const { return startup_peak_bytes_ * 8.0 / 1000.0; }
  bool has_steady_window() const { return steady_windows_ > 0; }
  // Median kbit/s of the steady 1 s windows; none before the first one.
  std::optional<double> calm_kbps() const;

 private:
  struct Sample {
    double t_s;
    std::uint64_t bytes;
  };
  std::deque<Sample> window_;  // the samples of the last kWindowS (+ slack)
  std::optional<double> first_frame_s_;
  double peak_bytes_ = 0.0, startup_peak_bytes_ = 0.0;
  std::uint64_t steady_windows_ = 0;
  std::vector<float> steady_window_kbps_;
};

}  // namespace ocean::loadtest
