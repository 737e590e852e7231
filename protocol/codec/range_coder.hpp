// Adaptive binary range coder (LZMA-style: 32-bit range, 11-bit probabilities, shift-5 adaptation)
// plus adaptive Elias-gamma integer models built on it. Integer only; each chunk starts afresh.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace ocean::codec {

using BitModel = std::uint16_t;  // P(bit = 0) in units of 2^-11
inline constexpr BitModel kBitModelInit = 1024;

class RangeEncoder {
 public:
  explicit RangeEncoder(bool track_cost = false) : track_cost_(track_cost) {}
  void encode_bit(BitModel& p, int bit);
  void encode_direct(std::uint32_t value, int bits);  // equiprobable bits, MSB first
  // Flushes and returns the bytes (trailing zero bytes stripped: the decoder pads with zeros).
  std::vector<std::uint8_t> finish();
  double cost_bits() const { return cost_bits_; }  // ideal cost so far (statistics only)

 private:
  void shift_low();
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cache_size_ = 1;
  bool first_ = true;  // the first byte LZMA would emit is always 0 and is not sent
  std::vector<std::uint8_t> out_;
  bool track_cost_;
  double cost_bits_ = 0.0;
};

class RangeDecoder {
 public:
  explicit RangeDecoder(std::span<const std::uint8_t> in);
  int decode_bit(BitModel& p);
  std::uint32_t decode_direct(int bits);

 private:
  std::uint8_t next_byte() { return pos_ < in_.size() ? in_[pos_++] : (++pos_, 0); }
  void normalize();
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t code_ = 0;
};

// Unsigned integers v < 2^kMaxBits as Elias gamma of v + 1: the bit length in unary with one
// adaptive model per position, then the two leading mantissa bits adaptive, the rest direct.
struct UIntModel {
  static constexpr int kMaxBits = 40;
  std::array<BitModel, kMaxBits + 1> length;
  std::array<std::array<BitModel, 3>, kMaxBits + 1> mantissa;
  UIntModel();
};

// Signed integers: a zero flag, a sign, then |v| - 1 as UIntModel.
struct SIntModel {
  BitModel zero = kBitModelInit;
  BitModel sign = kBitModelInit;
  UIntModel magnitude;
};

void encode_uint(RangeEncoder& rc, UIntModel& m, std::uint64_t v);
void encode_sint(RangeEncoder& rc, SIntModel& m, std::int64_t v);
void encode_nonzero(RangeEncoder& rc, SIntModel& m, std::int64_t v);  // v != 0, no zero flag

// Decoders return false when the data cannot come from the matching encoder (length overflow).
bool decode_uint(RangeDecoder& rc, UIntModel& m, std::uint64_t& v);
bool decode_sint(RangeDecoder& rc, SIntModel& m, std::int64_t& v);
bool decode_nonzero(RangeDecoder& rc, SIntModel& m, std::int64_t& v);

}  // namespace ocean::codec
