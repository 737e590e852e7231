// ByteReader: takes little-endian fields off the front of a fuzz input; past the end it yields
// zeros, so a harness can carve structure out of any input without checking lengths everywhere.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace ocean::fuzz {

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : rest_(bytes) {}

  bool empty() const { return rest_.empty(); }

  template <typename T>
  T take() {
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T) && !rest_.empty(); ++i) {
      value = static_cast<T>(value | static_cast<T>(static_cast<T>(rest_[0]) << (8 * i)));
      rest_ = rest_.subspan(1);
    }
    return value;
  }

  std::span<const std::uint8_t> take_bytes(std::size_t n) {
    const std::span<const std::uint8_t> out = rest_.first(std::min(n, rest_.size()));
    rest_ = rest_.subspan(out.size());
    return out;
  }

 private:
  std::span<const std::uint8_t> rest_;
};

}  // namespace ocean::fuzz
