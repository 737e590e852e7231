#include "admission_budget.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::server {

void AdmissionBudget::observe(const LoadPeriod& period) {
  if (period.wall_s <= 0.0) return;
  const double waited = std::clamp(period.waited_s / period.wall_s, 0.0, 1.0);
  const double busy = std::clamp((period.ran_s + period.waited_s) / period.wall_s, waited, 1.0);
  // Smoothed over a few seconds: one slow second (a key tick, a burst of joins) moves the
  // capacity a little, a lasting load moves it all the way.
  busy_share_ = 0.6 * busy_share_ + 0.4 * busy;
  wait_share_ = 0.6 * wait_share_ + 0.4 * waited;
  sessions_ = 0.6 * sessions_ + 0.4 * std::max(0.0, period.sessions);
  const double served = period.served_s < 0.0 || period.ran_s <= 0.0 ? 1.0 : std::clamp(period.served_s / period.ran_s, 0.0, 1.0);
  served_share_ = 0.6 * served_share_ + 0.4 * served;
  if (session_load() < 0.5 * target_load_) {
    capacity_ = kUnlimited;
    return;
  }
  const double projected = std::floor(sessions_ * target_load_ / session_load());
  capacity_ = std::max(floor_, static_cast<std::size_t>(projected));
}

}  // namespace ocean::server
