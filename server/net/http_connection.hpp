// HttpConnection: one request and one reply on an accepted socket, then close (Connection: close).
// Enough for Prometheus scrapes and Kubernetes probes; a silent client is cut off after a deadline.
#pragma once

#include "http_request_parser.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <system_error>

namespace ocean::server {

struct HttpReply {
  int status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body;

  std::string to_wire(bool include_body) const;  // status line, headers, body
};

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  using Handler = std::function<HttpReply(const HttpRequest&)>;
  using DoneCallback = std::function<void(const std::shared_ptr<HttpConnection>&)>;
  // A request refused for the client's fault: "http_bad_request", "http_method" or "http_timeout".
  using RefusedCallback = std::function<void(std::string_view reason, const std::string& peer)>;

  HttpConnection(asio::ip::tcp::socket socket, Handler handler, DoneCallback on_done, RefusedCallback on_refused = {});

  void start();
  void stop();  // closes the socket; pending operations complete with an error

 private:
  void arm_deadline(std::chrono::steady_clock::duration limit);  // then: http_timeout, closed
  void do_read();
  void do_write(const HttpReply& reply, bool include_body);
  void finish();
  void refused(std::string_view reason);

  asio::ip::tcp::socket socket_;
  asio::steady_timer deadline_;
  Handler handler_;
  DoneCallback on_done_;
  RefusedCallback on_refused_;
  HttpRequestParser parser_;
  std::array<char, 2048> read_buffer_{};
  std::string reply_bytes_;
  bool finished_ = false;
};

}  // namespace ocean::server
