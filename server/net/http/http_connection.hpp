// HttpConnection: one request and one reply on an accepted socket, then close (Connection: close).
// Enough for Prometheus scrapes and Kubernetes probes; a silent client is cut off after a deadline.
#pragma once

#include "byte_stream.hpp"
#include "http_request_parser.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>

namespace ocean::server {

struct HttpReply {
  HttpReply() = default;
  HttpReply(int status_code, std::string type, std::string text, std::shared_ptr<const std::string> shared = nullptr,
            std::string more_headers = {})
      : status(status_code),
        content_type(std::move(type)),
        body(std::move(text)),
        shared_body(std::move(shared)),
        headers(std::move(more_headers)) {}

  int status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body;
  // A large body every reply shares instead of `body` (the web viewer's files): a connection then
  // holds a pointer to it, not a copy, so many slow downloads cost little memory.
  std::shared_ptr<const std::string> shared_body = nullptr;
  std::string headers;  // more header lines, each ending in \r\n (Content-Encoding, ETag, ...)

  std::string_view content() const { return shared_body ? std::string_view(*shared_body) : std::string_view(body); }
  // The status line and headers, then `body` when include_body and the body is not shared.
  std::string to_wire(bool include_body) const;
};

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  using Handler = std::function<HttpReply(const HttpRequest&)>;
  using DoneCallback = std::function<void(const std::shared_ptr<HttpConnection>&)>;
  // A request refused for the client's fault: "http_bad_request", "http_method", "http_timeout" or
  // "http_evicted" (HttpServer made room for a newcomer).
  using RefusedCallback = std::function<void(std::string_view reason, const std::string& peer)>;

  // tls: the page's context (--tls-cert: https), null in the clear.
  HttpConnection(asio::ip::tcp::socket socket, Handler handler, DoneCallback on_done, RefusedCallback on_refused = {},
                 const std::shared_ptr<asio::ssl::context>& tls = nullptr);

  void start();
  void stop();  // closes the socket; pending operations complete with an error
  // Still waiting for its request (not yet writing a reply): what a slow or silent client holds.
  bool reading() const { return !writing_ && !finished_; }
  std::chrono::steady_clock::time_point opened() const { return opened_; }
  void evict();  // closes it as http_evicted

 private:
  void arm_deadline(std::chrono::steady_clock::duration limit);  // then: http_timeout, closed
  void do_read();
  void do_write(const HttpReply& reply, bool include_body);
  void finish();
  void refused(std::string_view reason);

  ByteStream stream_;
  asio::steady_timer deadline_;
  Handler handler_;
  DoneCallback on_done_;
  RefusedCallback on_refused_;
  HttpRequestParser parser_;
  std::array<char, 2048> read_buffer_{};
  std::string reply_bytes_;
  std::shared_ptr<const std::string> reply_body_;  // a shared body, written after reply_bytes_
  std::chrono::steady_clock::time_point opened_ = std::chrono::steady_clock::now();
  bool writing_ = false;
  bool finished_ = false;
};

}  // namespace ocean::server
