// HttpRequestParser: reads just enough of an HTTP/1.x request (the request line, then the blank
// line ending the headers) for the metrics and probe endpoints. Answers good / bad / need-more.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ocean::server {

struct HttpRequest {
  std::string method;  // "GET"
  std::string target;  // "/metrics" (a query string is dropped)
  std::string version; // "HTTP/1.1"
  // The two headers the page server reads (values as sent, empty when absent): which encodings
  // the client takes, and the ETag of the copy it holds.
  std::string accept_encoding;
  std::string if_none_match;
};

class HttpRequestParser {
 public:
  enum class Result { good, bad, need_more };
  static constexpr std::size_t kMaxRequestBytes = 8192;  // request line and headers together

  // Feed bytes as they arrive; once good or bad, further input is ignored.
  Result consume(std::string_view bytes);
  const HttpRequest& request() const { return request_; }

 private:
  Result parse_request_line(std::string_view line);
  void parse_headers(std::string_view headers);

  std::string buffer_;
  Result result_ = Result::need_more;
  HttpRequest request_;
};

}  // namespace ocean::server
