// TcpLink: one client's TCP connection as a StreamLink. Reads size-prefixed messages through a
// TcpFramer and hands each whole message on; writes the queued messages one at a time
// (SocketStreamLink: bounded, paced), so a slow or silent reader never grows server memory.
#pragma once

#include "socket_stream_link.hpp"
#include "tcp_framer.hpp"

#include <array>
#include <cstdint>

namespace ocean::server {

struct TransportContext;  // transport_context.hpp

class TcpLink final : public SocketStreamLink {
 public:
  TcpLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes)
      : SocketStreamLink(std::move(socket), max_queue_bytes) {}
  // Its row's factory (config/stream_transports.hpp).
  static std::shared_ptr<StreamLink> open(asio::ip::tcp::socket socket, const TransportContext& context);

  std::string_view transport() const override { return "tcp"; }
  void set_max_message_bytes(std::size_t bytes) override { framer_.set_max_message_bytes(bytes); }
  std::size_t framer_buffered_bytes() const { return framer_.buffered_bytes(); }

 private:
  void do_read() override;
  void do_write() override;

  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 16 * 1024> read_buffer_{};
};

}  // namespace ocean::server
