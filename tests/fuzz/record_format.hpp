// The record layout shared by the multi-message harnesses and make_corpus: each record is a
// 1-byte tag, a 2-byte little-endian length and that many bytes, so one input replays a sequence
// (e.g. every chunk of a frame) and libFuzzer mutates each part.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "byte_reader.hpp"

namespace ocean::fuzz {

struct Record {
  std::uint8_t tag = 0;
  std::span<const std::uint8_t> bytes;
};

inline bool next_record(ByteReader& in, Record& record) {
  if (in.empty()) return false;
  record.tag = in.take<std::uint8_t>();
  const std::uint16_t length = in.take<std::uint16_t>();
  record.bytes = in.take_bytes(length);
  return true;
}

inline void append_record(std::vector<std::uint8_t>& out, std::uint8_t tag, std::span<const std::uint8_t> bytes) {
  out.push_back(tag);
  out.push_back(static_cast<std::uint8_t>(bytes.size()));
  out.push_back(static_cast<std::uint8_t>(bytes.size() >> 8));
  out.insert(out.end(), bytes.begin(), bytes.end());
}

}  // namespace ocean::fuzz
