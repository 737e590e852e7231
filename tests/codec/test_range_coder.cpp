// Range coder and integer models round-trip, compress skewed data, and survive stripped zeros.
#include "range_coder.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace ocean::codec;

TEST_CASE("bits, direct bits and integers round-trip") {
  std::mt19937_64 rng(42);
  std::geometric_distribution<int> geo(0.3);
  std::bernoulli_distribution rare(0.03);
  std::vector<int> bits;
  std::vector<std::int64_t> ints;
  std::vector<std::uint32_t> direct;
  RangeEncoder enc;
  BitModel bm = kBitModelInit;
  SIntModel sm;
  UIntModel um;
  for (int i = 0; i < 20000; ++i) {
    bits.push_back(rare(rng) ? 1 : 0);
    enc.encode_bit(bm, bits.back());
    std::int64_t v = geo(rng) * (rng() & 1 ? 1 : -1);
    if (i % 97 == 0) v = static_cast<std::int64_t>(rng() >> 26) * (i % 2 ? 1 : -1);  // large values too
    ints.push_back(v);
    encode_sint(enc, sm, v);
    direct.push_back(static_cast<std::uint32_t>(rng() & 0x1FFF));
    enc.encode_direct(direct.back(), 13);
    encode_uint(enc, um, static_cast<std::uint64_t>(i));
  }
  const auto bytes = enc.finish();
  RangeDecoder dec(bytes);
  BitModel dbm = kBitModelInit;
  SIntModel dsm;
  UIntModel dum;
  for (int i = 0; i < 20000; ++i) {
    REQUIRE(dec.decode_bit(dbm) == bits[i]);
    std::int64_t v;
    REQUIRE(decode_sint(dec, dsm, v));
    REQUIRE(v == ints[i]);
    REQUIRE(dec.decode_direct(13) == direct[i]);
    std::uint64_t u;
    REQUIRE(decode_uint(dec, dum, u));
    REQUIRE(u == static_cast<std::uint64_t>(i));
  }
}

TEST_CASE("adaptive bits compress a skewed source close to its entropy") {
  RangeEncoder enc;
  BitModel bm = kBitModelInit;
  std::mt19937_64 rng(1);
  std::bernoulli_distribution rare(0.02);
  const int n = 100000;
  for (int i = 0; i < n; ++i) enc.encode_bit(bm, rare(rng) ? 1 : 0);
  const auto bytes = enc.finish();
  const double entropy_bytes = n * 0.1414 / 8;  // H(0.02) = 0.1414 bits
  CHECK(bytes.size() < entropy_bytes * 1.15);
}

TEST_CASE("an empty or all-zero message flushes to nothing and decodes from padding") {
  RangeEncoder enc;
  SIntModel m;
  for (int i = 0; i < 5; ++i) encode_sint(enc, m, 0);
  const auto bytes = enc.finish();
  CHECK(bytes.size() <= 1);
  RangeDecoder dec(bytes);
  SIntModel dm;
  for (int i = 0; i < 5; ++i) {
    std::int64_t v = 1;
    REQUIRE(decode_sint(dec, dm, v));
    CHECK(v == 0);
  }
}

TEST_CASE("an overlong integer is refused") {
  RangeEncoder enc;
  BitModel ones = kBitModelInit;
  UIntModel m;
  for (int i = 0; i < 60; ++i) enc.encode_bit(m.length[std::min(i, UIntModel::kMaxBits)], 1);
  (void)ones;
  const auto bytes = enc.finish();
  RangeDecoder dec(bytes);
  UIntModel dm;
  std::uint64_t v;
  CHECK_FALSE(decode_uint(dec, dm, v));
}
