// libFuzzer harness for verify_cookie (the check that proves a UDP source before the server keeps
// or sends anything for it). Input: 8 bytes of "now" (Unix ms, LE), then the cookie bytes.
// Invariants: only the exact cookie mint_cookie() gives for the claimed session, this sender and
// the claimed expiry is ok; a wrong size is bad_size; the same bytes from another port are refused.
#include <algorithm>
#include <cstdint>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"
#include "udp_cookie.hpp"

using namespace ocean::server;

namespace {

CookieKey fuzz_key() {
  CookieKey key{};
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<std::uint8_t>(0xA5 ^ i);
  return key;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const CookieKey key = fuzz_key();
  const asio::ip::udp::endpoint sender(asio::ip::make_address_v4("192.0.2.7"), 40000);
  const asio::ip::udp::endpoint other(asio::ip::make_address_v4("192.0.2.7"), 40001);

  ocean::fuzz::ByteReader in({data, size});
  const auto now = static_cast<std::int64_t>(in.take<std::uint64_t>());
  const std::span<const std::uint8_t> cookie = in.take_bytes(size);

  const CookieCheck check = verify_cookie(key, cookie, sender, now);
  FUZZ_REQUIRE(to_string(check.status) != nullptr);
  if (cookie.size() != kCookieBytes) {
    FUZZ_REQUIRE(check.status == CookieStatus::bad_size);
    return 0;
  }
  FUZZ_REQUIRE(check.status != CookieStatus::bad_size);
  if (check.status != CookieStatus::ok) return 0;

  std::int64_t expiry = 0;
  for (int i = 0; i < 8; ++i) expiry |= static_cast<std::int64_t>(cookie[8 + i]) << (8 * i);
  FUZZ_REQUIRE(now < expiry);
  const std::int64_t lifetime = 1000;
  const Cookie genuine = mint_cookie(key, check.session_id, sender, expiry - lifetime, lifetime);
  FUZZ_REQUIRE(std::equal(genuine.begin(), genuine.end(), cookie.begin(), cookie.end()));
  FUZZ_REQUIRE(verify_cookie(key, cookie, other, now).status == CookieStatus::bad_mac);
  return 0;
}
