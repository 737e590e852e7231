// BundleKey: the chunks of one FrameBundle datagram, oldest first (the unacked copies, then the
// newest frame), as the key sessions with the same history share its bytes by. Fixed size, so
// that building and looking one up per session and tick allocates nothing.
#pragma once

#include "chunk_format.hpp"
#include "server_config.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace ocean::server {

struct BundleKey {
  static constexpr std::size_t kMaxChunks = static_cast<std::size_t>(kMaxUdpRedundancy) + 1;
  std::array<const codec::Chunk*, kMaxChunks> chunks{};
  std::size_t count = 0;

  void push(const codec::Chunk* chunk) {
    if (count < kMaxChunks) chunks[count++] = chunk;
  }
  void drop_oldest() {
    if (count == 0) return;
    std::move(chunks.begin() + 1, chunks.begin() + static_cast<std::ptrdiff_t>(count), chunks.begin());
    --count;
  }
  std::span<const codec::Chunk* const> view() const { return {chunks.data(), count}; }
  bool operator==(const BundleKey& other) const {
    return count == other.count && std::equal(chunks.begin(), chunks.begin() + static_cast<std::ptrdiff_t>(count),
                                              other.chunks.begin());
  }
};

struct BundleKeyHash {
  std::size_t operator()(const BundleKey& key) const {
    std::uint64_t h = key.count;
    for (const codec::Chunk* chunk : key.view())
      h = (h ^ static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(chunk))) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

}  // namespace ocean::server
