// ByteStream: the bytes of one accepted TCP connection, in the clear or through TLS (--tls-cert:
// the browser's https page and wss socket). Readers and writers see the same calls either way; a
// TLS connection's handshake comes first (handshake() completes at once in the clear). It holds
// a reference to its own socket, so it stays where it was built (inside its connection object).
#pragma once

#include <asio/ip/tcp.hpp>
#include <asio/post.hpp>
#include <asio/ssl/context.hpp>
#include <asio/ssl/stream.hpp>
#include <asio/write.hpp>

#include <memory>
#include <system_error>
#include <utility>

namespace ocean::server {

class ByteStream {
 public:
  // tls: the server's context when this listener serves TLS, null in the clear.
  ByteStream(asio::ip::tcp::socket socket, const std::shared_ptr<asio::ssl::context>& tls)
      : socket_(std::move(socket)), context_(tls) {
    if (context_) tls_ = std::make_unique<asio::ssl::stream<asio::ip::tcp::socket&>>(socket_, *context_);
  }
  ByteStream(const ByteStream&) = delete;
  ByteStream& operator=(const ByteStream&) = delete;

  asio::ip::tcp::socket& socket() { return socket_; }
  const asio::ip::tcp::socket& socket() const { return socket_; }
  bool is_tls() const { return tls_ != nullptr; }

  template <class Handler>
  void handshake(Handler&& handler) {
    if (!tls_) return asio::post(socket_.get_executor(), [h = std::forward<Handler>(handler)]() mutable { h(std::error_code()); });
    tls_->async_handshake(asio::ssl::stream_base::server, std::forward<Handler>(handler));
  }
  template <class Buffers, class Handler>
  void read_some(const Buffers& buffers, Handler&& handler) {
    if (tls_) return tls_->async_read_some(buffers, std::forward<Handler>(handler));
    socket_.async_read_some(buffers, std::forward<Handler>(handler));
  }
  template <class Buffers, class Handler>
  void write(const Buffers& buffers, Handler&& handler) {
    if (tls_) return asio::async_write(*tls_, buffers, std::forward<Handler>(handler));
    asio::async_write(socket_, buffers, std::forward<Handler>(handler));
  }

 private:
  asio::ip::tcp::socket socket_;
  std::shared_ptr<asio::ssl::context> context_;  // kept alive while the connection lives (a reload replaces the server's)
  std::unique_ptr<asio::ssl::stream<asio::ip::tcp::socket&>> tls_;
};

}  // namespace ocean::server
