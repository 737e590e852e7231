#include "session_hub.hpp"

#include "tcp_link.hpp"
#include "tick_clock.hpp"

namespace ocean::server {

namespace {

Tick tick_now(const ServerConfig& config) {
  const std::int64_t tick = TickClock(config.tick_rate_hz, config.epoch_unix_ms).tick_at(system_unix_ns());
  return static_cast<Tick>(std::max<std::int64_t>(0, tick));
}

SessionCoreHost host_of(Server& server) {
  return SessionCoreHost{server.config(), server.schedule(), server.metrics(), server.cookie_key(), server,
                         server.udp_port(),
                         [&server](const sim::SceneParams& scene, std::int64_t from) { server.request_scene(scene, from); }};
}

}  // namespace

SessionHub::SessionHub(Server& server, SessionCoreOptions options)
    : server_(server), core_(host_of(server), options, tick_now(server.config())) {
  server_.set_connection_handler([this](asio::ip::tcp::socket socket) { on_connection(std::move(socket)); });
  server_.set_datagram_handler([this](std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& sender) {
    core_.on_datagram(bytes, sender, now_instant());
    server_.flush();
  });
  server_.set_frame_sink([this](const std::shared_ptr<const TickFrames>& frames) {
    core_.on_frames(frames, now_instant());
    server_.flush();
  });
  server_.set_stop_handler([this] { core_.stop(); });
}

void SessionHub::on_connection(asio::ip::tcp::socket socket) {
  if (const int bytes = core_.options().socket_send_buffer_bytes; bytes > 0) {
    std::error_code ignored;
    socket.set_option(asio::socket_base::send_buffer_size(bytes), ignored);
  }
  core_.open(std::make_shared<TcpLink>(std::move(socket), core_.options().send_queue_bytes), now_instant());
}

}  // namespace ocean::server
