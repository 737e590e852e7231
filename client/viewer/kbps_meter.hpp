// KbpsMeter: the received rate the HUD shows, from a running byte total sampled a few times a
// second, smoothed over about a second at five samples per second. A total below the previous one
// (a counter that started again) gives no sample and becomes the new baseline, instead of an
// unsigned difference near 2^64 that would read as 10^13 kbit/s for the next minute.
#pragma once

#include <cstdint>

namespace ocean::viewer {

class KbpsMeter {
 public:
  // Takes the total bytes received by now_s (seconds on any monotonic clock); returns the rate.
  double update(std::uint64_t total_bytes, double now_s) {
    if (sampled_ && now_s > last_s_ && total_bytes >= last_bytes_) {
      const double instant = static_cast<double>(total_bytes - last_bytes_) * 8.0 / 1000.0 / (now_s - last_s_);
      kbps_ += (instant - kbps_) * kSmoothing;
    }
    sampled_ = true;
    last_bytes_ = total_bytes;
    last_s_ = now_s;
    return kbps_;
  }
  double kbps() const { return kbps_; }

 private:
  static constexpr double kSmoothing = 0.3;  // per sample
  bool sampled_ = false;
  std::uint64_t last_bytes_ = 0;
  double last_s_ = 0.0, kbps_ = 0.0;
};

}  // namespace ocean::viewer
