#include "http_request_parser.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
using Result = HttpRequestParser::Result;

TEST_CASE("a complete GET parses", "[http]") {
  HttpRequestParser parser;
  REQUIRE(parser.consume("GET /metrics?x=1 HTTP/1.1\r\nHost: a\r\nAccept: */*\r\n\r\n") == Result::good);
  CHECK(parser.request().method == "GET");
  CHECK(parser.request().target == "/metrics");
  CHECK(parser.request().version == "HTTP/1.1");
}

TEST_CASE("a request split across reads needs more until the blank line", "[http]") {
  HttpRequestParser parser;
  CHECK(parser.consume("GET /hea") == Result::need_more);
  CHECK(parser.consume("lthz HTTP/1.0\r\n") == Result::need_more);
  CHECK(parser.consume("\r") == Result::need_more);
  CHECK(parser.consume("\n") == Result::good);
  CHECK(parser.request().target == "/healthz");
}

TEST_CASE("malformed or oversized requests are bad", "[http]") {
  for (const char* bad : {"GET /metrics\r\n\r\n", "GET metrics HTTP/1.1\r\n\r\n", "GET /m HTTP/2\r\n\r\n",
                          "GET  /m HTTP/1.1\r\n\r\n", "\r\n\r\n"}) {
    INFO(bad);
    HttpRequestParser parser;
    CHECK(parser.consume(bad) == Result::bad);
  }
  HttpRequestParser flood;
  CHECK(flood.consume(std::string(HttpRequestParser::kMaxRequestBytes, 'a')) == Result::need_more);
  CHECK(flood.consume("a") == Result::bad);
  CHECK(flood.consume("\r\n\r\n") == Result::bad);  // stays bad
}

TEST_CASE("Accept-Encoding and If-None-Match are read, whatever their names' case", "[http]") {
  HttpRequestParser parser;
  REQUIRE(parser.consume("GET /ocean-web.wasm HTTP/1.1\r\nHost: a\r\naccept-ENCODING:  gzip, deflate, br \r\n"
                         "If-None-Match: \"00ff\"\r\nX-Other: gzip\r\n\r\n") == Result::good);
  CHECK(parser.request().accept_encoding == "gzip, deflate, br");
  CHECK(parser.request().if_none_match == "\"00ff\"");
  HttpRequestParser none;
  REQUIRE(none.consume("GET / HTTP/1.0\r\nX-Accept-Encoding: gzip\r\nbroken line\r\n\r\n") == Result::good);
  CHECK(none.request().accept_encoding.empty());
  CHECK(none.request().if_none_match.empty());
}
