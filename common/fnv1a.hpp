// FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3): the project's one fingerprint
// of bytes - frame hashes, the decode memo's keys, the web files' ETags. Not a cryptographic hash.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::common {

inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;
inline constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

// h with `size` more bytes mixed in (start from kFnvOffset).
inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = kFnvOffset) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * kFnvPrime;
  return h;
}

}  // namespace ocean::common
