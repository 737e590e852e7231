#include "baseline_tracker.hpp"

#include "wire_limits.hpp"

namespace ocean::server {
namespace {

void keep_newer(std::optional<codec::StateId>& slot, codec::StateId state) {
  if (!slot || state.tick > slot->tick) slot = state;
}

}  // namespace

void BaselineTracker::record_sent(std::uint32_t tick, codec::StateId state, bool reliable, bool key) {
  if (key) {
    reset();
    root_ = tick;
  }
  sent_[tick] = state;
  if (reliable) {
    reliable_ = state;
    if (on_grid(tick)) reliable_aligned_ = state;
  }
  const std::uint32_t keep = 2 * protocol::kMaxBaselineGap;
  while (!sent_.empty() && sent_.begin()->first + keep < tick) sent_.erase(sent_.begin());
}

void BaselineTracker::on_ack(const protocol::AckWindow& window) {
  bool newest_found = false;
  for (std::uint32_t age = 0; age <= protocol::kAckWindowTicks && age <= window.latest_tick; ++age) {
    const std::uint32_t tick = window.latest_tick - age;
    if (!window.contains(tick)) continue;
    const auto found = sent_.find(tick);
    if (found == sent_.end()) continue;
    if (!newest_found) keep_newer(acked_, found->second);
    newest_found = true;
    if (on_grid(tick)) {
      keep_newer(acked_aligned_, found->second);
      return;  // older acked ticks are no better
    }
  }
}

std::optional<codec::StateId> BaselineTracker::choose(std::uint32_t tick, bool over_udp,
                                                      const std::function<bool(codec::StateId)>& encoder_has) const {
  auto usable = [&](const std::optional<codec::StateId>& state) {
    return state && state->tick < tick && tick - state->tick <= protocol::kMaxBaselineGap && encoder_has(*state);
  };
  if (over_udp) {
    if (usable(acked_aligned_)) return acked_aligned_;
    if (usable(acked_)) return acked_;
  }
  if (usable(reliable_aligned_)) return reliable_aligned_;
  if (usable(reliable_)) return reliable_;
  return std::nullopt;
}

void BaselineTracker::reset() {
  sent_.clear();
  acked_.reset();
  acked_aligned_.reset();
  reliable_.reset();
  reliable_aligned_.reset();
  root_.reset();
}

}  // namespace ocean::server
