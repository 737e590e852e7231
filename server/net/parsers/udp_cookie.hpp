// UdpCookie: proof that a UDP sender owns the address it claims, issued over TCP after the
// handshake and echoed in UDP packets. An HMAC (crypto_auth, HMAC-SHA512-256) over the session,
// the client's IP and port and an expiry lets the server check it without keeping per-address state.
// Time is passed in; the key comes from randombytes at startup or a file shared by replicas.
#pragma once

#include <asio/ip/udp.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace ocean::server {

inline constexpr std::size_t kCookieKeyBytes = 32;  // crypto_auth_KEYBYTES
inline constexpr std::size_t kCookieMacBytes = 32;  // crypto_auth_BYTES
// Layout: session id (u64 LE) | expiry in Unix ms (i64 LE) | MAC.
inline constexpr std::size_t kCookieBytes = 8 + 8 + kCookieMacBytes;

using CookieKey = std::array<std::uint8_t, kCookieKeyBytes>;
using Cookie = std::array<std::uint8_t, kCookieBytes>;

CookieKey random_cookie_key();  // libsodium's randombytes; aborts only if libsodium cannot start

inline constexpr std::int64_t kDefaultCookieLifetimeMs = 30'000;

// A cookie valid for `client` until now + lifetime.
Cookie mint_cookie(const CookieKey& key, std::uint64_t session_id, const asio::ip::udp::endpoint& client,
                   std::int64_t now_unix_ms, std::int64_t lifetime_ms = kDefaultCookieLifetimeMs);

enum class CookieStatus { ok, expired, bad_mac, bad_size };
const char* to_string(CookieStatus status);  // "ok", "expired", ... as used in logs and metrics

struct CookieCheck {
  CookieStatus status = CookieStatus::bad_size;
  std::uint64_t session_id = 0;  // meaningful only when status == ok
};

// Size first, then the MAC (constant time), then the expiry: an expired cookie is reported as such
// only when it is genuine. Expired means now_unix_ms >= expiry.
CookieCheck verify_cookie(const CookieKey& key, std::span<const std::uint8_t> cookie,
                          const asio::ip::udp::endpoint& sender, std::int64_t now_unix_ms);

}  // namespace ocean::server
