// ArrivalClock: sliding-window minimum of arrival offsets.
#include "arrival_clock.hpp"

#include <algorithm>
#include <stdexcept>

namespace ocean::client {

ArrivalClock::ArrivalClock(double tick_period_s, std::size_t window) : period_(tick_period_s), offsets_(window) {
  if (!(tick_period_s > 0.0)) throw std::invalid_argument("ArrivalClock: tick_period_s must be > 0");
  if (window == 0) throw std::invalid_argument("ArrivalClock: window must be >= 1 arrival");
}

void ArrivalClock::observe(Tick tick, double arrival_s) {
  offsets_[next_] = arrival_s - static_cast<double>(tick) * period_;
  next_ = (next_ + 1) % offsets_.size();
  filled_ = std::min(filled_ + 1, offsets_.size());
  offset_ = *std::min_element(offsets_.begin(), offsets_.begin() + static_cast<std::ptrdiff_t>(filled_));
  if (filled_ < 8) return;
  sorted_.assign(offsets_.begin(), offsets_.begin() + static_cast<std::ptrdiff_t>(filled_));
  const auto p95 = sorted_.begin() + static_cast<std::ptrdiff_t>((filled_ * 95 + 99) / 100 - 1);
  std::nth_element(sorted_.begin(), p95, sorted_.end());
  jitter_ = *p95 - *offset_;
}

void ArrivalClock::reset() {
  next_ = 0;
  filled_ = 0;
  offset_.reset();
  jitter_ = 0.0;
}

}  // namespace ocean::client
