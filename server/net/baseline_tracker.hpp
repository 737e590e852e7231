// BaselineTracker: the Quake 3 model for one session. Remembers which encoded state it sent for
// each tick, learns from acks which ones the client holds, and names the state the next delta is
// predicted from: the newest acked one (UDP), or the last one queued on TCP (ordered, reliable).
#pragma once

#include "ack_window.hpp"
#include "state_hash.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>

namespace ocean::server {

class BaselineTracker {
 public:
  // reliable: queued on TCP, so the client will hold it without an ack.
  void record_sent(std::uint32_t tick, codec::StateId state, bool reliable);
  // Acks name ticks; the state sent for the newest acked tick becomes the UDP baseline.
  void on_ack(const protocol::AckWindow& window);
  // The baseline for a delta of `tick`: within kMaxBaselineGap and still held by the encoder.
  std::optional<codec::StateId> choose(std::uint32_t tick, bool over_udp,
                                       const std::function<bool(codec::StateId)>& encoder_has) const;
  void reset();  // a new scene: nothing sent before predicts anything after
  // True when `state` is the newest state the client acked: a UDP datagram predicted from it can
  // be decoded whatever order datagrams arrive in. A baseline only queued on TCP cannot (the key
  // may still be in flight), so deltas from it go on TCP behind it.
  bool is_acked(codec::StateId state) const { return acked_ && *acked_ == state; }
  std::optional<std::uint32_t> newest_acked() const { return acked_ ? std::optional(acked_->tick) : std::nullopt; }

 private:
  std::map<std::uint32_t, codec::StateId> sent_;  // the last 2 windows of ticks
  std::optional<codec::StateId> acked_;
  std::optional<codec::StateId> reliable_;
};

}  // namespace ocean::server
