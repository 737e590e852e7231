#include "http_server.hpp"

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

HttpServer::HttpServer(asio::io_context& context, const ListenAddress& address,
                                     HttpConnection::Handler handler, std::size_t max_connections, std::string_view purpose)
    : acceptor_(open_tcp_acceptor(context, address, purpose)),
      backoff_(context),
      handler_(std::move(handler)),
      max_connections_(max_connections) {}

void HttpServer::start() { do_accept(); }

void HttpServer::stop() {
  std::error_code ignored;
  acceptor_.close(ignored);
  backoff_.cancel();
  for (const auto& connection : connections_) connection->stop();
  connections_.clear();
}

void HttpServer::evict_oldest_reader() {
  std::shared_ptr<HttpConnection> oldest;
  for (const auto& connection : connections_)
    if (connection->reading() && (!oldest || connection->opened() < oldest->opened())) oldest = connection;
  if (oldest) oldest->evict();  // its done callback takes it out of connections_
}

void HttpServer::do_accept() {
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
    if (!error) admit(std::move(socket));
    do_accept();
  });
}

// One host may hold an eighth of the connections only, so it cannot keep out everyone else; and
// when every connection is taken, the one that has waited longest for its request (slowloris,
// a silent socket) makes room for the newcomer: a reader that sends nothing useful cannot keep the
// page from anyone, while downloads under way are never cut.
void HttpServer::admit(asio::ip::tcp::socket socket) {
  std::error_code ignored;
  const asio::ip::address peer = socket.remote_endpoint(ignored).address();
  const bool limited = max_connections_ > 0;
  const auto held = per_host_.find(peer);
  const std::size_t from_peer = held == per_host_.end() ? 0 : held->second;
  const bool host_full = from_peer >= std::max<std::size_t>(1, max_connections_ / 8);
  if (limited && !host_full && connections_.size() >= max_connections_) evict_oldest_reader();
  if (limited && (connections_.size() >= max_connections_ || host_full)) {
    if (on_refused_) on_refused_("http_busy", peer.to_string());
    socket.close(ignored);
    return;
  }
  if (limited) ++per_host_[peer];
  auto connection = std::make_shared<HttpConnection>(
      std::move(socket), handler_,
      [this, peer, limited](const std::shared_ptr<HttpConnection>& done) {
        connections_.erase(done);
        if (limited && --per_host_[peer] == 0) per_host_.erase(peer);
      },
      on_refused_, tls_ ? tls_() : nullptr);
  connections_.insert(connection);
  connection->start();
}

}  // namespace ocean::server
