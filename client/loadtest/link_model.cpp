// The rate limiter is a serialiser (Bottleneck): a packet leaves when the bytes queued before it
// have, which is a token bucket with a one-packet burst; its queue is bounded in bytes (tail drop).
#include "link_model.hpp"

#include <algorithm>

namespace ocean::loadtest {

LinkModel::LinkModel(const LinkSpec& spec, std::uint64_t seed, std::shared_ptr<Bottleneck> shared)
    : spec_(spec), rng_(seed ^ 0x9E3779B97F4A7C15ull), bottleneck_(std::move(shared)) {
  if (!bottleneck_ && spec_.rate_bps > 0) bottleneck_ = std::make_shared<Bottleneck>(spec_.rate_bps);
}

double LinkModel::uniform() {
  // splitmix64: tiny, good enough for impairment decisions, the same on every platform.
  std::uint64_t z = (rng_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

void LinkModel::schedule(std::vector<std::uint8_t> bytes, double due) {
  pending_.push(InFlight{due, order_++, std::move(bytes)});
}

void LinkModel::send(std::vector<std::uint8_t> bytes, double now) {
  ++stats_.offered;
  if (spec_.loss > 0 && uniform() < spec_.loss) {
    ++stats_.lost;
    return;
  }
  double left_link = now;
  if (bottleneck_) {
    const auto left = bottleneck_->admit(now, bytes.size(), static_cast<double>(spec_.queue_bytes));
    if (!left) {
      ++stats_.queue_drops;
      return;
    }
    left_link = *left;
  }
  const double base = spec_.delay_ms * 1e-3;
  const double jitter = spec_.jitter_ms * 1e-3 * (2.0 * uniform() - 1.0);
  double due = left_link + base + jitter;
  if (spec_.retransmit_loss > 0) {
    // Each 1460-byte segment may be lost. Linux finds the loss once a later segment is acked and a
    // quarter round trip more has passed (RACK, RFC 8985; a 30 Hz stream sends the next within
    // 33 ms) and sends it again: it arrives 1.25 round trips and that gap late, and the FIFO below
    // holds everything sent after it.
    const std::size_t segments = std::max<std::size_t>(1, (bytes.size() + 1459) / 1460);
    for (std::size_t i = 0; i < segments; ++i)
      if (uniform() < spec_.retransmit_loss) {
        due += 1.25 * (2.0 * base) + 0.033;
        ++stats_.retransmitted;
        break;
      }
  }
  if (spec_.reorder > 0 && uniform() < spec_.reorder) {
    // Skips the queue of in-flight packets: it may arrive before ones sent earlier.
    due = left_link + base - spec_.jitter_ms * 1e-3;
    ++stats_.reordered;
  } else {
    due = std::max(due, last_in_order_);
    last_in_order_ = due;
  }
  if (spec_.duplicate > 0 && uniform() < spec_.duplicate) {
    ++stats_.duplicated;
    schedule(bytes, due + 0.001);
  }
  schedule(std::move(bytes), due);
}

}  // namespace ocean::loadtest
