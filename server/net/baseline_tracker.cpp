#include "baseline_tracker.hpp"

#include "wire_limits.hpp"

namespace ocean::server {

void BaselineTracker::record_sent(std::uint32_t tick, codec::StateId state, bool reliable) {
  sent_[tick] = state;
  if (reliable) reliable_ = state;
  const std::uint32_t keep = 2 * protocol::kMaxBaselineGap;
  while (!sent_.empty() && sent_.begin()->first + keep < tick) sent_.erase(sent_.begin());
}

void BaselineTracker::on_ack(const protocol::AckWindow& window) {
  for (std::uint32_t age = 0; age <= protocol::kAckWindowTicks && age <= window.latest_tick; ++age) {
    const std::uint32_t tick = window.latest_tick - age;
    if (!window.contains(tick)) continue;
    const auto found = sent_.find(tick);
    if (found == sent_.end()) continue;
    if (!acked_ || found->second.tick > acked_->tick) acked_ = found->second;
    return;  // the newest acked tick we sent is the best baseline
  }
}

std::optional<codec::StateId> BaselineTracker::choose(std::uint32_t tick, bool over_udp,
                                                      const std::function<bool(codec::StateId)>& encoder_has) const {
  auto usable = [&](const std::optional<codec::StateId>& state) {
    return state && state->tick < tick && tick - state->tick <= protocol::kMaxBaselineGap && encoder_has(*state);
  };
  std::optional<codec::StateId> best;
  if (usable(reliable_)) best = reliable_;
  if (over_udp && usable(acked_) && (!best || acked_->tick > best->tick)) best = acked_;
  return best;
}

void BaselineTracker::reset() {
  sent_.clear();
  acked_.reset();
  reliable_.reset();
}

}  // namespace ocean::server
