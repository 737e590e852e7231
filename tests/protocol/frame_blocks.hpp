// Helpers for frame record blocks (frame_records.hpp) in the tests: blocks written byte by byte,
// for the layouts encode_frame_block() never makes, and record comparison (FrameRecord views its
// payload, so it has no operator==).
#pragma once

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <ostream>
#include <span>
#include <vector>

#include "frame_records.hpp"

namespace ocean::protocol::test {

// A block written field by field: v() appends a LEB128 varint (as PROTOCOL.md 7 describes it, not
// through the library), raw() appends bytes as they are.
struct RawBlock {
  Bytes bytes;

  RawBlock& v(std::uint64_t value) {
    while (value >= 0x80) {
      bytes.push_back(static_cast<std::uint8_t>(value | 0x80));
      value >>= 7;
    }
    bytes.push_back(static_cast<std::uint8_t>(value));
    return *this;
  }
  RawBlock& raw(std::initializer_list<std::uint8_t> more) {
    bytes.insert(bytes.end(), more.begin(), more.end());
    return *this;
  }
  RawBlock& payload(std::size_t n, std::uint8_t fill = 0xAB) {
    bytes.insert(bytes.end(), n, fill);
    return *this;
  }
  // One whole single-chunk record: tick offset, lag, count 1, length, payload.
  RawBlock& record(std::uint64_t back, std::uint64_t lag, std::size_t length = 2) {
    return v(back).v(lag).v(0).v(length).payload(length);
  }
};

inline bool same_record(const FrameRecord& a, const FrameRecord& b) {
  return a.tick == b.tick && a.baseline == b.baseline && a.key == b.key && a.index == b.index && a.count == b.count &&
         std::ranges::equal(a.payload, b.payload);
}

inline bool same_records(std::span<const FrameRecord> a, std::span<const FrameRecord> b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), same_record);
}

}  // namespace ocean::protocol::test

namespace ocean::protocol {

// For Catch's messages when a comparison of records fails.
inline std::ostream& operator<<(std::ostream& os, const FrameRecord& r) {
  return os << "{tick " << r.tick << ", baseline " << r.baseline << (r.key ? ", key" : ", delta") << ", chunk "
            << r.index << "/" << r.count << ", " << r.payload.size() << " bytes}";
}

}  // namespace ocean::protocol
