// HttpServer: one HTTP listener answering GET/HEAD with a handler - the Prometheus endpoint and
// probes (/metrics, /healthz, /readyz) and the browser viewer's page (--web-listen, WebFiles), on
// the probes' io_context. Owns its acceptor and the open connections so stop() ends them all.
#pragma once

#include "http_connection.hpp"
#include "listen_address.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <functional>
#include <memory>
#include <map>
#include <set>
#include <string_view>

namespace ocean::server {

class HttpServer {
 public:
  // Binds at once; throws std::system_error naming the address when it cannot. max_connections
  // (0: no limit) bounds the open connections, and one host may hold an eighth of them; one more
  // from a host at its share is closed at once and counted as http_busy, one more when all are
  // taken closes the connection that has waited longest for its request (http_evicted).
  HttpServer(asio::io_context& context, const ListenAddress& address, HttpConnection::Handler handler,
                    std::size_t max_connections = 0, std::string_view purpose = "metrics");

  void set_refused_callback(HttpConnection::RefusedCallback callback) { on_refused_ = std::move(callback); }
  // Serves https: each accepted connection takes the context this gives then (TlsCredentials).
  void set_tls(std::function<std::shared_ptr<asio::ssl::context>()> tls) { tls_ = std::move(tls); }
  void start();
  void stop();  // closes the acceptor and every open connection
  asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }

 private:
  void do_accept();
  void admit(asio::ip::tcp::socket socket);  // or refuse it as http_busy
  void evict_oldest_reader();

  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer backoff_;  // after EMFILE
  HttpConnection::Handler handler_;
  HttpConnection::RefusedCallback on_refused_;
  std::function<std::shared_ptr<asio::ssl::context>()> tls_;
  std::set<std::shared_ptr<HttpConnection>> connections_;
  std::size_t max_connections_ = 0;
  std::map<asio::ip::address, std::size_t> per_host_;  // open connections by peer address, when limited
};

// Opens, configures (SO_REUSEADDR) and binds a listening TCP acceptor; used for every TCP listener.
asio::ip::tcp::acceptor open_tcp_acceptor(asio::io_context& context, const ListenAddress& address,
                                          std::string_view purpose);

}  // namespace ocean::server
