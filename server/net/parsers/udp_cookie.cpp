#include "udp_cookie.hpp"

#include <sodium.h>

#include <cstdlib>
#include <cstring>

namespace ocean::server {
namespace {

static_assert(kCookieKeyBytes == crypto_auth_KEYBYTES);
static_assert(kCookieMacBytes == crypto_auth_BYTES);

// The authenticated message: session | expiry | IPv6 (IPv4 mapped) address | port.
constexpr std::size_t kMessageBytes = 8 + 8 + 16 + 2;

void put_le64(std::uint8_t* out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::uint64_t get_le64(const std::uint8_t* in) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value |= static_cast<std::uint64_t>(in[i]) << (8 * i);
  return value;
}

std::array<std::uint8_t, kMessageBytes> message(std::uint64_t session_id, std::int64_t expiry_unix_ms,
                                                const asio::ip::udp::endpoint& client) {
  std::array<std::uint8_t, kMessageBytes> m{};
  put_le64(m.data(), session_id);
  put_le64(m.data() + 8, static_cast<std::uint64_t>(expiry_unix_ms));
  const asio::ip::address address = client.address();
  const asio::ip::address_v6 v6 =
      address.is_v4() ? asio::ip::make_address_v6(asio::ip::v4_mapped, address.to_v4()) : address.to_v6();
  const auto bytes = v6.to_bytes();
  std::memcpy(m.data() + 16, bytes.data(), 16);
  m[32] = static_cast<std::uint8_t>(client.port() >> 8);
  m[33] = static_cast<std::uint8_t>(client.port() & 0xff);
  return m;
}

}  // namespace

CookieKey random_cookie_key() {
  if (sodium_init() < 0) std::abort();  // no usable entropy source: nothing safe can follow
  CookieKey key;
  randombytes_buf(key.data(), key.size());
  return key;
}

Cookie mint_cookie(const CookieKey& key, std::uint64_t session_id, const asio::ip::udp::endpoint& client,
                   std::int64_t now_unix_ms, std::int64_t lifetime_ms) {
  Cookie cookie{};
  const auto m = message(session_id, now_unix_ms + lifetime_ms, client);
  std::memcpy(cookie.data(), m.data(), 16);  // session and expiry travel in clear
  crypto_auth(cookie.data() + 16, m.data(), m.size(), key.data());
  return cookie;
}

const char* to_string(CookieStatus status) {
  switch (status) {
    case CookieStatus::ok: return "ok";
    case CookieStatus::expired: return "expired";
    case CookieStatus::bad_mac: return "bad_mac";
    case CookieStatus::bad_size: break;
  }
  return "bad_size";
}

CookieCheck verify_cookie(const CookieKey& key, std::span<const std::uint8_t> cookie,
                          const asio::ip::udp::endpoint& sender, std::int64_t now_unix_ms) {
  if (cookie.size() != kCookieBytes) return {CookieStatus::bad_size, 0};
  const std::uint64_t session_id = get_le64(cookie.data());
  const auto expiry = static_cast<std::int64_t>(get_le64(cookie.data() + 8));
  const auto m = message(session_id, expiry, sender);
  if (crypto_auth_verify(cookie.data() + 16, m.data(), m.size(), key.data()) != 0) return {CookieStatus::bad_mac, 0};
  if (now_unix_ms >= expiry) return {CookieStatus::expired, 0};
  return {CookieStatus::ok, session_id};
}

}  // namespace ocean::server
