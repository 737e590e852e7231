// JsonValue: a small reader for the JSON this project writes (ocean-loadtest's summaries, for
// --merge): objects, arrays, numbers, strings, true/false/null. There is no JSON library in the
// build (common/json_writer.hpp only writes), and a summary needs nothing more.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocean::loadtest {

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool flag = false;
  double number = 0.0;
  std::string text;  // a string's value; a number's digits as written (exact integers)
  std::vector<JsonValue> items;
  std::map<std::string, JsonValue> fields;

  const JsonValue* find(const std::string& key) const;
  // Integers beyond 2^53 keep their digits: read them from text.
  std::optional<std::uint64_t> as_uint() const;
};

// Parses one JSON value (surrounding white space allowed); nullopt with `error` set (where and
// what) when the text is not JSON.
std::optional<JsonValue> parse_json(std::string_view text, std::string& error);

}  // namespace ocean::loadtest
