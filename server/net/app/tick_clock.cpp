#include "tick_clock.hpp"

#include <stdexcept>
#include <string>

namespace ocean::server {
namespace {

constexpr std::int64_t kNsPerSecond = 1'000'000'000;

// Floor division for a possibly negative numerator and a positive denominator.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

}  // namespace

TickClock::TickClock(int rate_hz, std::int64_t epoch_unix_ms, int max_catch_up)
    : rate_hz_(rate_hz), epoch_ns_(epoch_unix_ms * 1'000'000), max_catch_up_(max_catch_up) {
  if (rate_hz < 1) throw std::invalid_argument("TickClock: rate_hz must be >= 1, got " + std::to_string(rate_hz));
  if (max_catch_up < 0)
    throw std::invalid_argument("TickClock: max_catch_up must be >= 0, got " + std::to_string(max_catch_up));
}

std::int64_t TickClock::tick_at(std::int64_t unix_ns) const {
  // Split into whole seconds and a remainder so (elapsed * rate) cannot overflow 64 bits.
  const std::int64_t elapsed = unix_ns - epoch_ns_;
  const std::int64_t seconds = floor_div(elapsed, kNsPerSecond);
  const std::int64_t remainder = elapsed - seconds * kNsPerSecond;  // in [0, 1e9)
  return seconds * rate_hz_ + remainder * rate_hz_ / kNsPerSecond;
}

std::int64_t TickClock::deadline_ns(std::int64_t tick) const {
  const std::int64_t seconds = floor_div(tick, rate_hz_);
  const std::int64_t within = tick - seconds * rate_hz_;  // in [0, rate)
  // ceil(within * 1e9 / rate): the first nanosecond whose floor maps to `tick`.
  const std::int64_t offset = (within * kNsPerSecond + rate_hz_ - 1) / rate_hz_;
  return epoch_ns_ + seconds * kNsPerSecond + offset;
}

double TickClock::sim_time_s(std::int64_t tick) const {
  // Whole seconds and the fraction separately keep full precision for large tick counts.
  const std::int64_t seconds = floor_div(tick, rate_hz_);
  return static_cast<double>(seconds) + static_cast<double>(tick - seconds * rate_hz_) / rate_hz_;
}

std::optional<TickDecision> TickClock::decide(std::int64_t unix_ns, std::optional<std::int64_t> last_tick) const {
  const std::int64_t due = tick_at(unix_ns);
  if (!last_tick) return TickDecision{due, 0, false};
  const std::int64_t next = *last_tick + 1;
  if (due < next) return std::nullopt;
  const std::int64_t also_due = due - next;
  if (also_due <= max_catch_up_) return TickDecision{next, 0, also_due > 0};
  return TickDecision{due, also_due, true};
}

}  // namespace ocean::server
