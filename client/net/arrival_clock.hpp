// ArrivalClock: estimates where the server's tick clock is on the client's clock from frame
// arrivals. Each arrival gives offset = arrival - tick * period; the minimum over a sliding window
// is the least-delayed frame, which rides out jitter (queueing only ever adds delay). The spread
// of the window above that minimum is the jitter a buffer must absorb. Pure.
#pragma once

#include "tick.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace ocean::client {

class ArrivalClock {
 public:
  // window: how many recent arrivals the minimum is taken over (>= 1).
  ArrivalClock(double tick_period_s, std::size_t window);

  void observe(Tick tick, double arrival_s);
  // Client time of tick 0 (the server clock offset plus the fastest one-way delay); nullopt
  // before the first arrival.
  std::optional<double> offset_s() const { return offset_; }
  // How much later than the fastest arrival 95 % of the window's arrivals came (0 before 8).
  double jitter_s() const { return jitter_; }
  double tick_period_s() const { return period_; }
  void reset();

 private:
  double period_;
  std::vector<double> offsets_;  // ring of the last `window` samples
  std::size_t next_ = 0;
  std::size_t filled_ = 0;
  std::optional<double> offset_;
  double jitter_ = 0.0;
  std::vector<double> sorted_;  // scratch
};

}  // namespace ocean::client
