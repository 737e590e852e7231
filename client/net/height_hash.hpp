// hash_heights: FNV-1a 64 over a reconstructed frame's heights as little-endian IEEE float bits.
// The web viewer reports it per tick and a native decoder fed the same messages must give the
// same value: WebAssembly decodes bit for bit what the native client does.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>

namespace ocean::client {

inline std::uint64_t hash_heights(std::span<const float> heights) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const float v : heights) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int byte = 0; byte < 4; ++byte) {
      h ^= (bits >> (8 * byte)) & 0xffu;
      h *= 0x100000001b3ull;
    }
  }
  return h;
}

}  // namespace ocean::client
