#include "ascii_text.hpp"

namespace ocean::server {

std::optional<std::size_t> first_non_ascii(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i)
    if (static_cast<unsigned char>(text[i]) >= 0x80) return i;
  return std::nullopt;
}

}  // namespace ocean::server
