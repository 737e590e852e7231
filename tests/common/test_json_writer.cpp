// JsonWriter: field order, both spacing styles, number formats, escaping and non-finite numbers.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <limits>

#include "common/json_writer.hpp"

using ocean::common::JsonWriter;

TEST_CASE("fields come out in call order, spaced or compact") {
  JsonWriter spaced;
  spaced.integer("frames", 120).fixed("fps", 59.876, 2).text("gl", "llvmpipe").boolean("ok", true);
  CHECK(spaced.str() == R"({"frames": 120, "fps": 59.88, "gl": "llvmpipe", "ok": true})");

  JsonWriter compact(JsonWriter::Style::compact);
  compact.integer("n_x", 64).number("time_s", 0.1, 17).integers("lod", std::array<int, 3>{1, 2, 3});
  CHECK(compact.str() == R"({"n_x":64,"time_s":0.10000000000000001,"lod":[1,2,3]})");
  CHECK(JsonWriter().str() == "{}");
}

TEST_CASE("numbers: printf's fixed and significant-digit forms, integers of any width, null for non-finite") {
  JsonWriter json;
  json.fixed("a", 1.0 / 3.0, 4).number("b", 1234567.0, 3).number("c", 0.5);
  json.integer("big", std::numeric_limits<std::uint64_t>::max()).integer("neg", std::int64_t{-7});
  json.fixed("inf", std::numeric_limits<double>::infinity(), 2).number("nan", std::numeric_limits<double>::quiet_NaN());
  CHECK(json.str() ==
        R"({"a": 0.3333, "b": 1.23e+06, "c": 0.5, "big": 18446744073709551615, "neg": -7, "inf": null, "nan": null})");
  // A value far beyond any fixed buffer still comes out whole.
  CHECK(JsonWriter().fixed("x", 1e300, 1).str().size() > 300);
}

TEST_CASE("strings are escaped: quotes, backslashes and control characters") {
  CHECK(JsonWriter::quote("closed: \"bye\"\\") == R"("closed: \"bye\"\\")");
  CHECK(JsonWriter::quote("a\nb\tc\x01") == R"("a\nb\tc\u0001")");
  CHECK(JsonWriter::quote("d\xc3\xa9j\xc3\xa0") == "\"d\xc3\xa9j\xc3\xa0\"");  // UTF-8 passes through
  JsonWriter json;
  json.text("key \"q\"", "v");
  CHECK(json.str() == R"({"key \"q\"": "v"})");
}

TEST_CASE("raw nests another writer's object") {
  JsonWriter inner(JsonWriter::Style::compact);
  inner.integer("x", 1);
  JsonWriter outer(JsonWriter::Style::compact);
  outer.raw("inner", inner.str()).integer("y", 2);
  CHECK(outer.str() == R"({"inner":{"x":1},"y":2})");
}
