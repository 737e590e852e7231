// libFuzzer harness for HttpRequestParser (the metrics / probe endpoint's reader). Input: byte 0
// picks the read size, the rest is the request. Invariants: fed in pieces it answers exactly what
// it answers fed at once; once good or bad it stays so; it never needs more than kMaxRequestBytes;
// a good request has a method, a target starting with '/' and no query string.
#include <algorithm>
#include <cstdint>
#include <string_view>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"
#include "http_request_parser.hpp"

using ocean::server::HttpRequestParser;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ocean::fuzz::ByteReader in({data, size});
  const std::size_t piece = 1 + in.take<std::uint8_t>() % 64;
  const std::span<const std::uint8_t> body = in.take_bytes(size);
  const std::string_view text(reinterpret_cast<const char*>(body.data()), body.size());

  HttpRequestParser whole;
  const HttpRequestParser::Result at_once = whole.consume(text);

  HttpRequestParser pieces;
  HttpRequestParser::Result result = HttpRequestParser::Result::need_more;
  for (std::size_t at = 0; at < text.size(); at += piece) {
    const HttpRequestParser::Result next = pieces.consume(text.substr(at, piece));
    if (result != HttpRequestParser::Result::need_more) FUZZ_REQUIRE(next == result);
    result = next;
  }
  if (!text.empty()) FUZZ_REQUIRE(result == at_once);
  if (text.size() > HttpRequestParser::kMaxRequestBytes) FUZZ_REQUIRE(at_once != HttpRequestParser::Result::need_more);

  if (at_once == HttpRequestParser::Result::good) {
    const auto& request = whole.request();
    FUZZ_REQUIRE(!request.method.empty() && !request.version.empty());
    FUZZ_REQUIRE(!request.target.empty() && request.target[0] == '/');
    FUZZ_REQUIRE(request.target.find('?') == std::string::npos);
    FUZZ_REQUIRE(pieces.request().method == request.method && pieces.request().target == request.target &&
                 pieces.request().version == request.version);
  }
  return 0;
}
