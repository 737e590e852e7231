#include "epoch.hpp"

#include "quoted.hpp"

#include <cctype>
#include <charconv>
#include <chrono>

namespace ocean::server {
namespace {

// Reads exactly `digits` decimal digits at text[pos..]; advances pos.
std::optional<int> read_digits(std::string_view text, std::size_t& pos, int digits) {
  if (pos + digits > text.size()) return std::nullopt;
  int value = 0;
  for (int i = 0; i < digits; ++i) {
    const char c = text[pos + i];
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = value * 10 + (c - '0');
  }
  pos += digits;
  return value;
}

bool expect(std::string_view text, std::size_t& pos, std::string_view options) {
  if (pos >= text.size() || options.find(text[pos]) == std::string_view::npos) return false;
  ++pos;
  return true;
}

std::optional<std::int64_t> parse_rfc3339_ms(std::string_view text) {
  using namespace std::chrono;
  std::size_t pos = 0;
  const auto y = read_digits(text, pos, 4);
  if (!y || !expect(text, pos, "-")) return std::nullopt;
  const auto mo = read_digits(text, pos, 2);
  if (!mo || !expect(text, pos, "-")) return std::nullopt;
  const auto d = read_digits(text, pos, 2);
  if (!d || !expect(text, pos, "Tt ")) return std::nullopt;
  const auto hh = read_digits(text, pos, 2);
  if (!hh || !expect(text, pos, ":")) return std::nullopt;
  const auto mm = read_digits(text, pos, 2);
  if (!mm || !expect(text, pos, ":")) return std::nullopt;
  const auto ss = read_digits(text, pos, 2);
  if (!ss || *hh > 23 || *mm > 59 || *ss > 60) return std::nullopt;

  std::int64_t frac_ms = 0;
  if (pos < text.size() && text[pos] == '.') {
    ++pos;
    int scale = 100, count = 0;
    while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
      frac_ms += (text[pos] - '0') * scale;  // digits past milliseconds are truncated
      scale /= 10;
      ++pos;
      ++count;
    }
    if (count == 0) return std::nullopt;
  }

  std::int64_t offset_min = 0;
  if (expect(text, pos, "Zz")) {
  } else if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) {
    const int sign = text[pos] == '-' ? -1 : 1;
    ++pos;
    const auto oh = read_digits(text, pos, 2);
    if (!oh || !expect(text, pos, ":")) return std::nullopt;
    const auto om = read_digits(text, pos, 2);
    if (!om || *oh > 23 || *om > 59) return std::nullopt;
    offset_min = sign * (*oh * 60 + *om);
  } else {
    return std::nullopt;  // RFC 3339 requires a zone
  }
  if (pos != text.size()) return std::nullopt;

  const year_month_day date{year{*y}, month{static_cast<unsigned>(*mo)}, day{static_cast<unsigned>(*d)}};
  if (!date.ok()) return std::nullopt;
  const std::int64_t days = sys_days{date}.time_since_epoch().count();
  const std::int64_t seconds = days * 86400 + *hh * 3600 + *mm * 60 + *ss - offset_min * 60;
  return seconds * 1000 + frac_ms;
}

}  // namespace

std::optional<std::int64_t> parse_epoch_ms(std::string_view text, std::string& error) {
  std::int64_t ms = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), ms);
  if (ec == std::errc() && end == text.data() + text.size()) return ms;
  if (const auto parsed = parse_rfc3339_ms(text)) return parsed;
  error = quoted(text) + " is neither Unix milliseconds (e.g. 1763744400000) nor an RFC 3339 time with a zone "
          "(e.g. 2026-11-21T17:00:00Z)";
  return std::nullopt;
}

}  // namespace ocean::server
