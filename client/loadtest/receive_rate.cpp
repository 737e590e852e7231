#include "receive_rate.hpp"

#include <algorithm>

namespace ocean::loadtest {

void ReceiveRate::sample(double t_s, std::uint64_t bytes) {
  window_.push_back(Sample{t_s, bytes});
  while (window_.size() > 1 && t_s - window_.front().t_s > kWindowS + kSlackS) window_.pop_front();
  if (window_.size() < 2) return;
  auto steady = [&](const Sample& start) { return first_frame_s_ && start.t_s >= *first_frame_s_; };
  // Of the windows ending here, the one starting earliest holds the most bytes; of those starting
  // from the first frame on, likewise the earliest such.
  auto per_window = [&](const Sample& start) {
    const double span = std::max(t_s - start.t_s, kWindowS);
    return static_cast<double>(bytes - start.bytes) * (kWindowS / span);
  };
  if (!steady(window_.front())) startup_peak_bytes_ = std::max(startup_peak_bytes_, per_window(window_.front()));
  const auto first_steady = std::find_if(window_.begin(), window_.end() - 1, steady);
  if (first_steady != window_.end() - 1) {
    peak_bytes_ = std::max(peak_bytes_, per_window(*first_steady));
    ++steady_windows_;
    // Whole 1 s windows only: a 100 ms interval holds 2, 3 or 4 datagrams, too coarse a rate.
    if (t_s - first_steady->t_s >= kWindowS - kSlackS)
      steady_window_kbps_.push_back(static_cast<float>(per_window(*first_steady) * 8.0 / 1000.0));
  }
}

std::optional<double> ReceiveRate::calm_kbps() const {
  if (steady_window_kbps_.empty()) return std::nullopt;
  std::vector<float> sorted = steady_window_kbps_;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>((sorted.size() - 1) / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  return *middle;
}

}  // namespace ocean::loadtest
