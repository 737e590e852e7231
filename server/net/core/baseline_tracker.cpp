#include "baseline_tracker.hpp"

#include "wire_limits.hpp"

namespace ocean::server {
namespace {

void keep_newer(std::optional<codec::StateId>& slot, codec::StateId state) {
  if (!slot || state.tick > slot->tick) slot = state;
}

}  // namespace

void BaselineTracker::record_sent(Tick tick, codec::StateId state, bool reliable, bool key) {
  if (key) {
    reset();
    root_ = state;
  }
  sent_[tick % kSentTicks] = Sent{tick, state, true};
  if (!newest_sent_ || tick >= newest_sent_->tick) newest_sent_ = state;
  if (reliable) {
    reliable_ = state;
    if (on_grid(tick)) reliable_aligned_ = state;
  }
}

std::optional<codec::StateId> BaselineTracker::sent_at(Tick tick) const {
  const Sent& slot = sent_[tick % kSentTicks];
  return slot.valid && slot.tick == tick ? std::optional(slot.state) : std::nullopt;
}

void BaselineTracker::on_ack(const protocol::AckWindow& window) {
  bool newest_found = false;
  std::size_t grid = 0;
  for (Tick age = 0; age <= protocol::kAckWindowTicks && age <= window.latest_tick; ++age) {
    const Tick tick = window.latest_tick - age;
    if (!window.contains(tick)) continue;
    // The key may be acked long after the window of sent frames moved on (a thin link).
    std::optional<codec::StateId> state = sent_at(tick);
    if (!state && root_ && root_->tick == tick) state = root_;
    if (!state) continue;
    if (!newest_found) keep_newer(acked_, *state);
    newest_found = true;
    if (on_grid(tick)) {
      if (grid == 0) keep_newer(acked_aligned_, *state);
      acked_grid_[grid++] = state;
      if (grid == kAckedGrid) return;  // older acked ticks are no better
    }
  }
  for (std::size_t i = grid; i < kAckedGrid; ++i) acked_grid_[i].reset();
}

std::optional<codec::StateId> BaselineTracker::choose_encoded(
    Tick tick, const std::function<bool(codec::StateId)>& encoded) const {
  for (const auto& state : acked_grid_)
    if (state && state->tick < tick && tick - state->tick <= protocol::kMaxBaselineGap && encoded(*state)) return state;
  return std::nullopt;
}

std::optional<codec::StateId> BaselineTracker::choose(Tick tick, bool over_udp,
                                                      const std::function<bool(codec::StateId)>& encoder_has) const {
  // The client keeps its newest complete frame however old: a key with nothing sent after it (one
  // that took long to arrive on a thin link) is a baseline up to the largest lag a record carries;
  // every other frame only within the ack window.
  const bool key_is_newest = root_ && newest_sent_ && *newest_sent_ == *root_;
  auto usable = [&](const std::optional<codec::StateId>& state) {
    if (!state || state->tick >= tick) return false;
    const Tick gap = tick - state->tick;
    const Tick limit = key_is_newest && *root_ == *state ? protocol::kMaxFrameLag : protocol::kMaxBaselineGap;
    return gap <= limit && encoder_has(*state);
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
  sent_.fill(Sent{});
  newest_sent_.reset();
  acked_.reset();
  acked_aligned_.reset();
  reliable_.reset();
  reliable_aligned_.reset();
  root_.reset();
  acked_grid_.fill(std::nullopt);
}

}  // namespace ocean::server
