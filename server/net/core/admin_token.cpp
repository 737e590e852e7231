#include "admin_token.hpp"

#include <sodium.h>

#include <array>

namespace ocean::server {

bool same_token(std::string_view given, std::string_view expected) {
  std::array<unsigned char, crypto_generichash_BYTES> a{}, b{};
  crypto_generichash(a.data(), a.size(), reinterpret_cast<const unsigned char*>(given.data()), given.size(), nullptr, 0);
  crypto_generichash(b.data(), b.size(), reinterpret_cast<const unsigned char*>(expected.data()), expected.size(), nullptr, 0);
  return sodium_memcmp(a.data(), b.data(), a.size()) == 0 && !expected.empty();
}

}  // namespace ocean::server
