#include "admission_budget.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::server {

void AdmissionBudget::observe(double busy_s, double wall_s, double sessions) {
  if (wall_s <= 0.0) return;
  const double share = std::clamp(busy_s / wall_s, 0.0, 1.0);
  // Smoothed over a few seconds: one slow second (a key tick, a burst of joins) does not close
  // the door, a lasting load does.
  busy_share_ = 0.6 * busy_share_ + 0.4 * share;
  if (busy_share_ > target_busy_) {
    const auto now_served = static_cast<std::size_t>(std::floor(sessions));
    capacity_ = std::min(capacity_, std::max<std::size_t>(now_served, 1));
  } else if (busy_share_ < 0.8 * target_busy_) {
    capacity_ = kUnlimited;
  }
}

}  // namespace ocean::server
