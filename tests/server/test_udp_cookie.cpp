#include "udp_cookie.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
using asio::ip::make_address;
using asio::ip::udp;

namespace {

constexpr std::int64_t kNow = 1795280400000;

}  // namespace

TEST_CASE("a fresh cookie verifies for its endpoint and names its session", "[cookie]") {
  const CookieKey key = random_cookie_key();
  for (const udp::endpoint& client : {udp::endpoint(make_address("192.0.2.7"), 50123),
                                     udp::endpoint(make_address("2001:db8::1"), 1)}) {
    const Cookie cookie = mint_cookie(key, 0x1122334455667788ull, client, kNow, 10'000);
    const CookieCheck check = verify_cookie(key, cookie, client, kNow + 9'999);
    CHECK(check.status == CookieStatus::ok);
    CHECK(check.session_id == 0x1122334455667788ull);
  }
}

TEST_CASE("a cookie expires at now + lifetime", "[cookie]") {
  const CookieKey key = random_cookie_key();
  const udp::endpoint client(make_address("192.0.2.7"), 50123);
  const Cookie cookie = mint_cookie(key, 7, client, kNow, 10'000);
  CHECK(verify_cookie(key, cookie, client, kNow + 9'999).status == CookieStatus::ok);
  CHECK(verify_cookie(key, cookie, client, kNow + 10'000).status == CookieStatus::expired);
  CHECK(verify_cookie(key, cookie, client, kNow + 1'000'000).status == CookieStatus::expired);
}

TEST_CASE("any changed byte, endpoint or key fails the MAC", "[cookie]") {
  const CookieKey key = random_cookie_key();
  const udp::endpoint client(make_address("192.0.2.7"), 50123);
  const Cookie cookie = mint_cookie(key, 7, client, kNow);

  int rejected = 0;
  for (std::size_t i = 0; i < cookie.size(); ++i) {
    Cookie tampered = cookie;
    tampered[i] ^= 0x01;
    rejected += verify_cookie(key, tampered, client, kNow).status == CookieStatus::bad_mac;
  }
  CHECK(rejected == static_cast<int>(cookie.size()));  // including a pushed-out expiry

  CHECK(verify_cookie(key, cookie, udp::endpoint(make_address("192.0.2.7"), 50124), kNow).status ==
        CookieStatus::bad_mac);
  CHECK(verify_cookie(key, cookie, udp::endpoint(make_address("192.0.2.8"), 50123), kNow).status ==
        CookieStatus::bad_mac);
  CHECK(verify_cookie(random_cookie_key(), cookie, client, kNow).status == CookieStatus::bad_mac);
  // An expired cookie from another endpoint is reported as forged, not as expired.
  CHECK(verify_cookie(key, cookie, udp::endpoint(make_address("192.0.2.8"), 50123), kNow + 10'000'000).status ==
        CookieStatus::bad_mac);
}

TEST_CASE("a cookie of the wrong size is refused before any crypto", "[cookie]") {
  const CookieKey key = random_cookie_key();
  const udp::endpoint client(make_address("192.0.2.7"), 50123);
  const Cookie cookie = mint_cookie(key, 7, client, kNow);
  CHECK(verify_cookie(key, std::span(cookie).first(kCookieBytes - 1), client, kNow).status == CookieStatus::bad_size);
  CHECK(verify_cookie(key, {}, client, kNow).status == CookieStatus::bad_size);
  std::vector<std::uint8_t> longer(cookie.begin(), cookie.end());
  longer.push_back(0);
  CHECK(verify_cookie(key, longer, client, kNow).status == CookieStatus::bad_size);
  CHECK(std::string(to_string(CookieStatus::bad_size)) == "bad_size");
}

TEST_CASE("random keys differ and a shared key works across servers", "[cookie]") {
  const CookieKey a = random_cookie_key();
  const CookieKey b = random_cookie_key();
  CHECK(a != b);
  const udp::endpoint client(make_address("198.51.100.1"), 4000);
  const CookieKey shared = a;  // as if read by two replicas from one --cookie-key-file
  CHECK(verify_cookie(shared, mint_cookie(a, 99, client, kNow), client, kNow).status == CookieStatus::ok);
}
