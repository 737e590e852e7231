// Bottleneck: the serialiser of one link direction's rate, which several LinkModels may share, so
// that a client's TCP and UDP traffic in one direction compete for the same bandwidth as they do
// on a real access link. A packet leaves when every byte queued before it (on any sharing model)
// has; the queue ahead of a packet is what decides a tail drop.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>

namespace ocean::loadtest {

class Bottleneck {
 public:
  explicit Bottleneck(double rate_bps) : rate_bps_(rate_bps) {}

  double rate_bps() const { return rate_bps_; }

  // Bytes still queued at `now` (admitted, not yet serialised).
  double backlog_bytes(double now) const { return std::max(0.0, free_at_ - now) * rate_bps_ / 8.0; }

  // Queues `bytes` offered at `now` and returns when its last bit leaves, or nullopt (nothing
  // queued) when the backlog plus this packet would exceed queue_limit_bytes.
  std::optional<double> admit(double now, std::size_t bytes, double queue_limit_bytes) {
    if (backlog_bytes(now) + static_cast<double>(bytes) > queue_limit_bytes) return std::nullopt;
    free_at_ = std::max(now, free_at_) + static_cast<double>(bytes) * 8.0 / rate_bps_;
    return free_at_;
  }

 private:
  double rate_bps_;
  double free_at_ = 0.0;  // when what is queued has left
};

}  // namespace ocean::loadtest
