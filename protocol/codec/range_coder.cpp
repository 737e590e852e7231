// Range coder and integer models (CODEC.md 6).
#include "range_coder.hpp"

#include <cmath>

namespace ocean::codec {
namespace {
constexpr int kProbBits = 11;
constexpr int kMoveBits = 5;
constexpr std::uint32_t kTop = 1u << 24;
}  // namespace

void RangeEncoder::shift_low() {
  if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
    const std::uint8_t carry = static_cast<std::uint8_t>(low_ >> 32);
    std::uint8_t temp = cache_;
    do {
      if (first_)
        first_ = false;  // always 0 (+0 carry): the decoder assumes it
      else
        out_.push_back(static_cast<std::uint8_t>(temp + carry));
      temp = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = static_cast<std::uint8_t>(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::encode_bit(BitModel& p, int bit) {
  const std::uint32_t bound = (range_ >> kProbBits) * p;
  if (track_cost_) cost_bits_ -= std::log2((bit ? (2048.0 - p) : p) / 2048.0);
  if (bit == 0) {
    range_ = bound;
    p = static_cast<BitModel>(p + (((1u << kProbBits) - p) >> kMoveBits));
  } else {
    low_ += bound;
    range_ -= bound;
    p = static_cast<BitModel>(p - (p >> kMoveBits));
  }
  while (range_ < kTop) {
    range_ <<= 8;
    shift_low();
  }
}

void RangeEncoder::encode_direct(std::uint32_t value, int bits) {
  cost_bits_ += bits;
  for (int i = bits - 1; i >= 0; --i) {
    range_ >>= 1;
    if ((value >> i) & 1u) low_ += range_;
    while (range_ < kTop) {
      range_ <<= 8;
      shift_low();
    }
  }
}

std::vector<std::uint8_t> RangeEncoder::finish() {
  // Any value in [low, low + range) decodes the same symbols; take the one with the most
  // trailing zero bits so the stripped tail is as long as possible.
  const std::uint64_t hi = low_ + range_;  // exclusive
  for (int b = 32; b >= 0; --b) {
    const std::uint64_t mask = (std::uint64_t{1} << b) - 1;
    const std::uint64_t v = (low_ + mask) & ~mask;
    if (v < hi) {
      low_ = v;
      break;
    }
  }
  for (int i = 0; i < 5; ++i) shift_low();
  while (!out_.empty() && out_.back() == 0) out_.pop_back();
  return std::move(out_);
}

RangeDecoder::RangeDecoder(std::span<const std::uint8_t> in) : in_(in) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
}

void RangeDecoder::normalize() {
  while (range_ < kTop) {
    range_ <<= 8;
    code_ = (code_ << 8) | next_byte();
  }
}

int RangeDecoder::decode_bit(BitModel& p) {
  const std::uint32_t bound = (range_ >> kProbBits) * p;
  int bit;
  if (code_ < bound) {
    range_ = bound;
    p = static_cast<BitModel>(p + (((1u << kProbBits) - p) >> kMoveBits));
    bit = 0;
  } else {
    code_ -= bound;
    range_ -= bound;
    p = static_cast<BitModel>(p - (p >> kMoveBits));
    bit = 1;
  }
  normalize();
  return bit;
}

std::uint32_t RangeDecoder::decode_direct(int bits) {
  std::uint32_t v = 0;
  for (int i = 0; i < bits; ++i) {
    range_ >>= 1;
    std::uint32_t bit = 0;
    if (code_ >= range_) {
      code_ -= range_;
      bit = 1;
    }
    v = (v << 1) | bit;
    normalize();
  }
  return v;
}

UIntModel::UIntModel() {
  length.fill(kBitModelInit);
  for (auto& m : mantissa) m.fill(kBitModelInit);
}

void encode_uint(RangeEncoder& rc, UIntModel& m, std::uint64_t v) {
  const std::uint64_t x = v + 1;
  int nb = 0;  // number of bits below the leading one
  while ((x >> (nb + 1)) != 0) ++nb;
  for (int i = 0; i < nb; ++i) rc.encode_bit(m.length[i], 1);
  rc.encode_bit(m.length[nb], 0);
  int ctx = 0;  // binary tree over the two leading mantissa bits
  for (int i = nb - 1; i >= 0; --i) {
    const int bit = static_cast<int>((x >> i) & 1u);
    if (nb - 1 - i < 2) {
      rc.encode_bit(m.mantissa[nb][ctx], bit);
      ctx = 1 + bit;
    } else {
      // remaining bits go in groups of at most 16 direct bits
      const int rest = i + 1;
      for (int done = 0; done < rest;) {
        const int take = rest - done > 16 ? 16 : rest - done;
        const int lo = rest - done - take;
        rc.encode_direct(static_cast<std::uint32_t>((x >> lo) & ((1u << take) - 1u)), take);
        done += take;
      }
      break;
    }
  }
}

bool decode_uint(RangeDecoder& rc, UIntModel& m, std::uint64_t& v) {
  int nb = 0;
  while (rc.decode_bit(m.length[nb]) == 1) {
    if (++nb >= UIntModel::kMaxBits) return false;
  }
  std::uint64_t x = 1;
  int ctx = 0;
  int i = nb - 1;
  for (; i >= 0 && nb - 1 - i < 2; --i) {
    const int bit = rc.decode_bit(m.mantissa[nb][ctx]);
    x = (x << 1) | static_cast<std::uint64_t>(bit);
    ctx = 1 + bit;
  }
  const int rest = i + 1;
  for (int done = 0; done < rest;) {
    const int take = rest - done > 16 ? 16 : rest - done;
    x = (x << take) | rc.decode_direct(take);
    done += take;
  }
  v = x - 1;
  return true;
}

void encode_nonzero(RangeEncoder& rc, SIntModel& m, std::int64_t v) {
  rc.encode_bit(m.sign, v < 0 ? 1 : 0);
  const std::uint64_t mag = v < 0 ? static_cast<std::uint64_t>(-(v + 1)) + 1 : static_cast<std::uint64_t>(v);
  encode_uint(rc, m.magnitude, mag - 1);
}

void encode_sint(RangeEncoder& rc, SIntModel& m, std::int64_t v) {
  rc.encode_bit(m.zero, v == 0 ? 0 : 1);
  if (v != 0) encode_nonzero(rc, m, v);
}

bool decode_nonzero(RangeDecoder& rc, SIntModel& m, std::int64_t& v) {
  const int neg = rc.decode_bit(m.sign);
  std::uint64_t mag1;
  if (!decode_uint(rc, m.magnitude, mag1)) return false;
  const std::int64_t mag = static_cast<std::int64_t>(mag1) + 1;  // < 2^40
  v = neg ? -mag : mag;
  return true;
}

bool decode_sint(RangeDecoder& rc, SIntModel& m, std::int64_t& v) {
  if (rc.decode_bit(m.zero) == 0) {
    v = 0;
    return true;
  }
  return decode_nonzero(rc, m, v);
}

}  // namespace ocean::codec
