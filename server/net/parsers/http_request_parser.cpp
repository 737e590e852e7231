#include "http_request_parser.hpp"

namespace ocean::server {
namespace {

bool is_token(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text)
    if (c <= ' ' || c >= 127) return false;
  return true;
}

}  // namespace

HttpRequestParser::Result HttpRequestParser::consume(std::string_view bytes) {
  if (result_ != Result::need_more) return result_;
  buffer_.append(bytes);
  const std::size_t end_of_headers = buffer_.find("\r\n\r\n");
  if (end_of_headers == std::string::npos) {
    result_ = buffer_.size() > kMaxRequestBytes ? Result::bad : Result::need_more;
    return result_;
  }
  if (end_of_headers > kMaxRequestBytes) return result_ = Result::bad;
  const std::size_t end_of_line = buffer_.find("\r\n");
  result_ = parse_request_line(std::string_view(buffer_).substr(0, end_of_line));
  if (result_ == Result::good) parse_headers(std::string_view(buffer_).substr(end_of_line + 2, end_of_headers - end_of_line));
  return result_;
}

// Header names are case-insensitive (RFC 9110 5.1); a value's surrounding blanks are not its own.
void HttpRequestParser::parse_headers(std::string_view headers) {
  const auto lower = [](std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return out;
  };
  while (!headers.empty()) {
    const std::size_t end = headers.find("\r\n");
    const std::string_view line = headers.substr(0, end);
    headers = end == std::string_view::npos ? std::string_view() : headers.substr(end + 2);
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    std::string_view value = line.substr(colon + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
    const std::string name = lower(line.substr(0, colon));
    if (name == "accept-encoding") request_.accept_encoding = value;
    else if (name == "if-none-match") request_.if_none_match = value;
  }
}

HttpRequestParser::Result HttpRequestParser::parse_request_line(std::string_view line) {
  const std::size_t first_space = line.find(' ');
  const std::size_t second_space = line.find(' ', first_space + 1);
  if (first_space == std::string_view::npos || second_space == std::string_view::npos) return Result::bad;
  const std::string_view method = line.substr(0, first_space);
  std::string_view target = line.substr(first_space + 1, second_space - first_space - 1);
  const std::string_view version = line.substr(second_space + 1);
  if (!is_token(method) || !is_token(target) || target.front() != '/' ||
      (version != "HTTP/1.1" && version != "HTTP/1.0"))
    return Result::bad;
  target = target.substr(0, target.find('?'));
  request_ = {std::string(method), std::string(target), std::string(version), {}, {}};
  return Result::good;
}

}  // namespace ocean::server
