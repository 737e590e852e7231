// How the server takes connections: one listener per stream transport the config enables, each
// accepted socket handed to the sessions, and accepts refused or paused while descriptors run out.
#include "server.hpp"

#include "server_log.hpp"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <chrono>
#include <sys/resource.h>

namespace ocean::server {

// One listener per stream transport the config enables, the primary one first.
void Server::open_listeners() {
  for (const StreamTransport& transport : stream_transports())
    if (const ListenAddress* address = listen_address(transport, config_))
      listeners_.push_back(std::make_unique<Listener>(context_, transport, *address));
}

std::optional<std::uint16_t> Server::port_of(std::string_view transport) const {
  for (const auto& listener : listeners_)
    if (listener->transport.name == transport) return listener->port;
  return std::nullopt;
}

void Server::do_accept(Listener& listener) {
  listener.acceptor.async_accept([this, &listener](std::error_code error, asio::ip::tcp::socket socket) {
    if (!listener.acceptor.is_open()) return;
    if (error == asio::error::no_descriptors || error.value() == ENFILE || error == asio::error::no_buffer_space ||
        error == asio::error::no_memory)
      return back_off_accept(listener);  // accepting again at once would spin on the same error
    if (!error && descriptors_low(socket, listener.transport.name)) {
      std::error_code ignored;
      socket.close(ignored);
    } else if (!error && connection_handler_) {
      connection_handler_(std::move(socket), listener.transport);
    } else if (!error) {
      std::error_code ignored;
      const auto peer = socket.remote_endpoint(ignored);
      log_reject(listener.transport.name, peer_text(peer), "sessions_unavailable");
      metrics_.rejects("sessions_unavailable").inc();
      socket.close(ignored);
    }
    do_accept(listener);
  });
}

// Descriptors are handed out lowest first: one this high means at most the reserve is free. The
// limit is read each time: an operator may raise it on a running server (prlimit).
bool Server::descriptors_low(asio::ip::tcp::socket& socket, std::string_view transport) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return false;
  const long descriptor_limit = static_cast<long>(limit.rlim_cur);
  if (descriptor_limit == 0 || socket.native_handle() < descriptor_limit - kReserveDescriptors) return false;
  metrics_.rejects("descriptors_low").inc();
  log_limited(spdlog::level::warn, "descriptors_low", "",
              "reject transport={} reason=descriptors_low: descriptor {} of {} (RLIMIT_NOFILE) would leave fewer than {} "
              "free; raise the limit (ulimit -n) or lower --max-clients",
              transport, socket.native_handle(), descriptor_limit, kReserveDescriptors);
  return true;
}

void Server::back_off_accept(Listener& listener) {
  metrics_.rejects("descriptors_exhausted").inc();
  log_limited(spdlog::level::warn, "descriptors_exhausted", "",
              "accept failed: no descriptors or buffers left; pausing accepts for 100 ms (raise ulimit -n)");
  listener.backoff.expires_after(std::chrono::milliseconds(100));
  listener.backoff.async_wait([this, &listener](std::error_code error) {
    if (!error && listener.acceptor.is_open()) do_accept(listener);
  });
}

}  // namespace ocean::server
