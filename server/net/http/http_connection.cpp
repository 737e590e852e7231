#include "http_connection.hpp"

#include <asio/write.hpp>

#include <chrono>

namespace ocean::server {
namespace {

constexpr auto kRequestDeadline = std::chrono::seconds(5);
// A reply gets the request's 5 s plus its size at this rate (128 kbit/s): the web viewer's
// module (about 0.7 MB) may take 50 s on a thin link, a /metrics page about 5 s.
constexpr double kSlowestReplyBytesPerS = 16 * 1024;

const char* reason_phrase(int status) {
  switch (status) {
    case 200: return "OK";
    case 304: return "Not Modified";
    case 400: return "Bad Request";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 503: return "Service Unavailable";
    default: return "Unknown";
  }
}

}  // namespace

std::string HttpReply::to_wire(bool include_body) const {
  std::string out = "HTTP/1.1 " + std::to_string(status) + " " + reason_phrase(status) + "\r\n";
  out += "Content-Type: " + content_type + "\r\n";
  // A 304 says nothing of the length: its headers stand for the copy the client holds (RFC 9110 8.6).
  if (status != 304) out += "Content-Length: " + std::to_string(content().size()) + "\r\n";
  out += headers;
  out += "Connection: close\r\n\r\n";
  if (include_body && !shared_body) out += body;
  return out;
}

HttpConnection::HttpConnection(asio::ip::tcp::socket socket, Handler handler, DoneCallback on_done,
                               RefusedCallback on_refused, const std::shared_ptr<asio::ssl::context>& tls)
    : stream_(std::move(socket), tls),
      deadline_(stream_.socket().get_executor()),
      handler_(std::move(handler)),
      on_done_(std::move(on_done)),
      on_refused_(std::move(on_refused)) {}

void HttpConnection::refused(std::string_view reason) {
  if (!on_refused_) return;
  std::error_code ignored;
  const auto peer = stream_.socket().remote_endpoint(ignored);
  on_refused_(reason, peer.address().to_string());
}

void HttpConnection::start() {
  arm_deadline(kRequestDeadline);  // the TLS handshake's too
  stream_.handshake([self = shared_from_this()](std::error_code error) {
    if (!error) return self->do_read();
    // Not a failure when it was cut short here (the deadline, an eviction, a stop): said already.
    if (!self->finished_ && error != asio::error::operation_aborted) self->refused("tls_handshake_failed");
    self->finish();
  });
}

void HttpConnection::arm_deadline(std::chrono::steady_clock::duration limit) {
  deadline_.expires_after(limit);  // an earlier wait completes with operation_aborted
  deadline_.async_wait([self = shared_from_this()](std::error_code error) {
    if (error) return;
    self->refused("http_timeout");  // too slow: give up on it
    self->finish();
  });
}

void HttpConnection::evict() {
  refused("http_evicted");
  finish();
}

void HttpConnection::stop() {
  std::error_code ignored;
  deadline_.cancel();
  stream_.socket().close(ignored);
}

void HttpConnection::do_read() {
  stream_.read_some(asio::buffer(read_buffer_), [self = shared_from_this()](std::error_code error, std::size_t n) {
    if (error) return self->finish();
    switch (self->parser_.consume(std::string_view(self->read_buffer_.data(), n))) {
      case HttpRequestParser::Result::need_more: return self->do_read();
      case HttpRequestParser::Result::bad:
        self->refused("http_bad_request");
        return self->do_write({400, "text/plain; charset=utf-8", "bad request\n"}, true);
      case HttpRequestParser::Result::good: {
        const HttpRequest& request = self->parser_.request();
        if (request.method != "GET" && request.method != "HEAD") {
          self->refused("http_method");
          return self->do_write({405, "text/plain; charset=utf-8", "only GET and HEAD\n"}, true);
        }
        return self->do_write(self->handler_(request), request.method == "GET");
      }
    }
  });
}

void HttpConnection::do_write(const HttpReply& reply, bool include_body) {
  writing_ = true;
  reply_bytes_ = reply.to_wire(include_body);
  if (include_body) reply_body_ = reply.shared_body;
  const std::size_t size = reply_bytes_.size() + (reply_body_ ? reply_body_->size() : 0);
  arm_deadline(kRequestDeadline + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(static_cast<double>(size) / kSlowestReplyBytesPerS)));
  const std::array<asio::const_buffer, 2> buffers{asio::buffer(reply_bytes_),
                                                  reply_body_ ? asio::buffer(*reply_body_) : asio::const_buffer()};
  stream_.write(buffers, [self = shared_from_this()](std::error_code error, std::size_t) {
    if (!error) {
      std::error_code ignored;
      self->stream_.socket().shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
    }
    self->finish();
  });
}

void HttpConnection::finish() {
  if (finished_) return;
  finished_ = true;
  stop();
  if (on_done_) on_done_(shared_from_this());
}

}  // namespace ocean::server
