// StateId names one version of a tick's decoder state; hash_state fingerprints a state so two
// sides (or two runs) can be compared cheaply.
#pragma once

#include "modal_model.hpp"
#include "tick.hpp"

#include <cstdint>

namespace ocean::codec {

// A tick may be encoded from several baselines; `serial` (unique within one Encoder) tells the
// versions apart. Acks name ticks; the server remembers which StateId it sent each client.
struct StateId {
  Tick tick = 0;
  std::uint32_t serial = 0;
  bool operator==(const StateId&) const = default;
  auto operator<=>(const StateId&) const = default;
};

// FNV-1a 64 over prev.re, prev.im, cur.re, cur.im as little-endian int64.
std::uint64_t hash_state(const ModalState& state);

}  // namespace ocean::codec
