// JsonWriter: one flat JSON object, written field by field in call order - for the tools' one-line
// --json summaries. Header-only, no dependencies beyond the standard library. Strings are escaped
// (quotes, backslashes, control characters), non-finite numbers are written as null, and each
// number says how it is formatted (fixed decimals or significant digits), so output stays stable.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdio>
#include <string>
#include <string_view>

namespace ocean::common {

class JsonWriter {
 public:
  enum class Style { spaced, compact };  // {"a": 1, "b": 2} or {"a":1,"b":2}

  explicit JsonWriter(Style style = Style::spaced) : style_(style) {}

  JsonWriter& text(std::string_view key, std::string_view value) { return raw(key, quote(value)); }
  JsonWriter& boolean(std::string_view key, bool value) { return raw(key, value ? "true" : "false"); }

  template <std::integral Int>
    requires(!std::same_as<Int, bool>)
  JsonWriter& integer(std::string_view key, Int value) {
    return raw(key, std::to_string(value));
  }

  // printf's %.<decimals>f: fixed-point with that many digits after the point.
  JsonWriter& fixed(std::string_view key, double value, int decimals) { return raw(key, format(value, 'f', decimals)); }
  // printf's %.<significant>g: 17 significant digits round-trip a double.
  JsonWriter& number(std::string_view key, double value, int significant = 6) {
    return raw(key, format(value, 'g', significant));
  }

  // An array of integers, e.g. [1, 2, 3].
  template <typename Range>
  JsonWriter& integers(std::string_view key, const Range& values) {
    std::string array = "[";
    for (const auto& v : values) {
      if (array.size() > 1) array += style_ == Style::spaced ? ", " : ",";
      array += std::to_string(v);
    }
    return raw(key, array + "]");
  }

  // A value that is already JSON (a nested object from another writer, an array).
  JsonWriter& raw(std::string_view key, std::string_view json) {
    out_ += out_.size() > 1 ? (style_ == Style::spaced ? ", " : ",") : "";
    out_ += quote(key);
    out_ += style_ == Style::spaced ? ": " : ":";
    out_ += json;
    return *this;
  }

  // The object so far, closed; the writer may go on adding fields.
  std::string str() const { return out_ + "}"; }

  // A JSON string literal: quotes and backslashes escaped, control characters as \n, \t or \u00XX;
  // other bytes (UTF-8) pass through.
  static std::string quote(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
      switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
            out += escaped;
          } else {
            out += c;
          }
      }
    }
    return out + "\"";
  }

 private:
  static std::string format(double value, char conversion, int precision) {
    if (!std::isfinite(value)) return "null";
    const auto print = [&](char* buffer, std::size_t size) {
      return conversion == 'f' ? std::snprintf(buffer, size, "%.*f", precision, value)
                               : std::snprintf(buffer, size, "%.*g", precision, value);
    };
    std::string out(static_cast<std::size_t>(print(nullptr, 0)), '\0');
    print(out.data(), out.size() + 1);
    return out;
  }

  Style style_;
  std::string out_ = "{";
};

}  // namespace ocean::common
