// same_bits: two float fields equal bit for bit (NaNs and signed zeros included), the codec's
// standard of equality between decoders.
#pragma once

#include <cstring>
#include <vector>

namespace ocean::codec::test {

inline bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

}  // namespace ocean::codec::test
