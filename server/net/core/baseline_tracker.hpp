// BaselineTracker: the Quake 3 model for one session. Remembers which encoded state it sent for
// each tick, learns from acks which ones the client holds, and names the state the next delta is
// predicted from: an acked one (UDP), or one queued on TCP (ordered, reliable). Baselines prefer
// ticks on a grid shared by every session (multiples of align_ticks), so sessions whose acks
// arrive at different ticks still ask for the same (tick, baseline) and share one encode.
#pragma once

#include "ack_window.hpp"
#include "state_hash.hpp"
#include "wire_limits.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

namespace ocean::server {

class BaselineTracker {
 public:
  explicit BaselineTracker(std::uint32_t align_ticks = 1) : align_(align_ticks ? align_ticks : 1) {}

  // reliable: queued on TCP, so the client will hold it without an ack. key: everything the
  // client held before is superseded (a new root; older states are never chosen again).
  void record_sent(Tick tick, codec::StateId state, bool reliable, bool key = false);
  // Acks name ticks; the states sent for the newest acked tick (and the newest on the grid) become
  // the UDP baselines.
  void on_ack(const protocol::AckWindow& window);
  // The baseline for a delta of `tick`: within kMaxBaselineGap and still held by the encoder; on
  // the grid when one qualifies.
  std::optional<codec::StateId> choose(Tick tick, bool over_udp,
                                       const std::function<bool(codec::StateId)>& encoder_has) const;
  // Under load, a baseline the stream already encoded this tick costs nothing more: the newest
  // state the client acked on the grid (among the last kAckedGrid) for which `encoded` holds.
  std::optional<codec::StateId> choose_encoded(Tick tick, const std::function<bool(codec::StateId)>& encoded) const;
  void reset();  // a new scene: nothing sent before predicts anything after
  // True when the client acked `state`: a UDP datagram predicted from it can be decoded whatever
  // order datagrams arrive in. A baseline only queued on TCP cannot (the key may still be in
  // flight), so deltas from it go on TCP behind it.
  bool is_acked(codec::StateId state) const {
    return (acked_ && *acked_ == state) || (acked_aligned_ && *acked_aligned_ == state);
  }
  std::optional<Tick> newest_acked() const { return acked_ ? std::optional(acked_->tick) : std::nullopt; }
  // The state this session's chain started from (its last key), for sharing policy.
  std::optional<Tick> root_tick() const { return root_ ? std::optional(root_->tick) : std::nullopt; }

 private:
  bool on_grid(Tick tick) const { return tick % align_ == 0; }
  std::optional<codec::StateId> sent_at(Tick tick) const;

  // What was sent for each of the last kSentTicks ticks, by tick modulo the ring: flat, so
  // acks and sends of thousands of sessions per tick touch no allocator.
  static constexpr std::size_t kSentTicks = 2 * protocol::kMaxBaselineGap;
  struct Sent {
    Tick tick = 0;
    codec::StateId state;
    bool valid = false;
  };
  std::uint32_t align_;
  std::array<Sent, kSentTicks> sent_{};
  std::optional<codec::StateId> newest_sent_;
  std::optional<codec::StateId> acked_, acked_aligned_;
  std::optional<codec::StateId> reliable_, reliable_aligned_;
  std::optional<codec::StateId> root_;  // the last key
  // The newest acked grid states of the latest ack, newest first.
  static constexpr std::size_t kAckedGrid = 4;
  std::array<std::optional<codec::StateId>, kAckedGrid> acked_grid_{};
};

}  // namespace ocean::server
