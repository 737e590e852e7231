// FNV-1a fingerprint of a modal state.
#include "state_hash.hpp"

namespace ocean::codec {

std::uint64_t hash_state(const ModalState& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (const auto* v : {&s.prev.re, &s.prev.im, &s.cur.re, &s.cur.im})
    for (std::int64_t x : *v)
      for (int b = 0; b < 8; ++b) {
        h ^= static_cast<std::uint64_t>(x) >> (8 * b) & 0xFF;
        h *= 1099511628211ull;
      }
  return h;
}

}  // namespace ocean::codec
