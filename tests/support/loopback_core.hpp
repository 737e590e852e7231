// LoopbackCore: the real SessionCore behind real loopback sockets on the test's own io_context -
// an acceptor whose connections become TcpLinks, a UDP socket, and a timer stepping the real
// simulation - so connection tests (reconnect, failover, UDP proof) meet the server's own rules.
// A completion already queued when the host is closed still runs, so handlers check `alive_`.
#pragma once

#include "core_rig.hpp"
#include "tcp_link.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/ip/udp.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <chrono>
#include <memory>

namespace ocean::test {

class LoopbackCore final : public server::DatagramSocket {
 public:
  // port 0: any free port. first_tick tells hosts apart (each streams its own timeline from it).
  LoopbackCore(asio::io_context& io, std::uint16_t port, Tick first_tick,
               server::ServerConfig config = core_test_config(), double step_s = 0.02)
      : acceptor_(io, asio::ip::tcp::endpoint(asio::ip::address_v4::loopback(), port)),
        udp_(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0)),
        timer_(io),
        step_s_(step_s),
        rig_(std::move(config), core_test_options(), *this, udp_.local_endpoint().port(), first_tick) {
    do_accept();
    do_receive();
    arm_timer();
  }
  ~LoopbackCore() override { close(); }
  LoopbackCore(const LoopbackCore&) = delete;
  LoopbackCore& operator=(const LoopbackCore&) = delete;

  std::uint16_t port() const { return port_; }
  CoreRig& rig() { return rig_; }
  const codec::EncodedFrame* sent_frame(Tick tick) const { return rig_.sent_frame(tick); }
  int hellos() { return static_cast<int>(rig_.metrics().sessions_started.value()); }  // sessions welcomed
  int byes() { return static_cast<int>(rig_.metrics().sessions_ended("client_bye").value()); }

  // The server goes away at once: every connection drops, nothing more is read or sent.
  void close() {
    if (!*alive_) return;
    *alive_ = false;
    rig_.core().abort("server_gone");
    std::error_code ignored;
    acceptor_.close(ignored);
    udp_.close(ignored);
    timer_.cancel();
  }

  bool send_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& to) override {
    std::error_code error;
    udp_.send_to(asio::buffer(bytes.data(), bytes.size()), to, 0, error);
    return !error;
  }

 private:
  static double now_s() { return server::now_instant().monotonic_s; }

  void do_accept() {
    acceptor_.async_accept([this, alive = alive_](std::error_code error, asio::ip::tcp::socket socket) {
      if (!*alive) return;
      if (!error) rig_.core().open(std::make_shared<server::TcpLink>(std::move(socket), 1u << 20), server::now_instant());
      do_accept();
    });
  }

  void do_receive() {
    udp_.async_receive_from(asio::buffer(datagram_), sender_, [this, alive = alive_](std::error_code error, std::size_t n) {
      if (!*alive) return;
      if (!error) rig_.core().on_datagram(std::span(datagram_.data(), n), sender_, server::now_instant());
      do_receive();
    });
  }

  void arm_timer() {
    timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(step_s_)));
    timer_.async_wait([this, alive = alive_](std::error_code error) {
      if (!*alive || error) return;
      rig_.step(now_s());
      arm_timer();
    });
  }

  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
  asio::ip::tcp::acceptor acceptor_;
  std::uint16_t port_ = acceptor_.local_endpoint().port();
  asio::ip::udp::socket udp_;
  asio::steady_timer timer_;
  double step_s_;
  std::array<std::uint8_t, 2048> datagram_{};
  asio::ip::udp::endpoint sender_;
  CoreRig rig_;
};

}  // namespace ocean::test
