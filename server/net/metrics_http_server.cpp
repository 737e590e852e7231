#include "metrics_http_server.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <system_error>

namespace ocean::server {

asio::ip::tcp::acceptor open_tcp_acceptor(asio::io_context& context, const ListenAddress& address,
                                          std::string_view purpose) {
  const asio::ip::tcp::endpoint endpoint(asio::ip::make_address(address.host), address.port);
  asio::ip::tcp::acceptor acceptor(context);
  std::error_code error;
  acceptor.open(endpoint.protocol(), error);
  if (!error) acceptor.set_option(asio::ip::tcp::acceptor::reuse_address(true), error);
  if (!error) acceptor.bind(endpoint, error);
  if (!error) acceptor.listen(asio::socket_base::max_listen_connections, error);
  if (error) throw std::system_error(error, "cannot listen for " + std::string(purpose) + " on " + address.to_string());
  return acceptor;
}

MetricsHttpServer::MetricsHttpServer(asio::io_context& context, const ListenAddress& address,
                                     HttpConnection::Handler handler, std::size_t max_connections, std::string_view purpose)
    : acceptor_(open_tcp_acceptor(context, address, purpose)),
      backoff_(context),
      handler_(std::move(handler)),
      max_connections_(max_connections) {}

void MetricsHttpServer::start() { do_accept(); }

void MetricsHttpServer::stop() {
  std::error_code ignored;
  acceptor_.close(ignored);
  backoff_.cancel();
  for (const auto& connection : connections_) connection->stop();
  connections_.clear();
}

void MetricsHttpServer::do_accept() {
  acceptor_.async_accept([this](std::error_code error, asio::ip::tcp::socket socket) {
    if (!acceptor_.is_open()) return;  // stopped
    if (error == asio::error::no_descriptors || error.value() == ENFILE) {
      // Accepting again at once would spin; the client acceptor keeps descriptors in reserve
      // for this endpoint, so this is rare and brief.
      backoff_.expires_after(std::chrono::milliseconds(20));
      return backoff_.async_wait([this](std::error_code e) {
        if (!e && acceptor_.is_open()) do_accept();
      });
    }
    if (!error) {
      std::error_code ignored;
      const asio::ip::address peer = socket.remote_endpoint(ignored).address();
      // One host may hold a share of the connections only, so it cannot keep out everyone else.
      const std::size_t per_host = max_connections_ > 0 ? std::max<std::size_t>(1, max_connections_ / 8) : 0;
      if (max_connections_ > 0 && (connections_.size() >= max_connections_ || per_host_[peer] >= per_host)) {
        if (per_host_[peer] == 0) per_host_.erase(peer);
        if (on_refused_) on_refused_("http_busy", peer.to_string());
        socket.close(ignored);
      } else {
        ++per_host_[peer];
        auto connection = std::make_shared<HttpConnection>(
            std::move(socket), handler_,
            [this, peer](const std::shared_ptr<HttpConnection>& done) {
              connections_.erase(done);
              if (--per_host_[peer] == 0) per_host_.erase(peer);
            },
            on_refused_);
        connections_.insert(connection);
        connection->start();
      }
    }
    do_accept();
  });
}

}  // namespace ocean::server
