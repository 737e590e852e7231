// StreamTestServer: a streaming server for the viewer tests - FakeServer (tests/client_net) behind
// a real loopback TCP acceptor, stepped by a timer at the profile's rate on its own thread, one
// client at a time. Destroying it and making another on the same port is a server restart.
#pragma once

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>
#include <asio/write.hpp>
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <thread>

#include "fake_server.hpp"
#include "tcp_framer.hpp"

namespace ocean::viewer::test {

class StreamTestServer {
 public:
  StreamTestServer(std::uint16_t port, std::uint8_t profile_id)
      : acceptor_(io_), socket_(io_), timer_(io_), profile_id_(profile_id) {
    const asio::ip::tcp::endpoint endpoint(asio::ip::address_v4::loopback(), port);
    acceptor_.open(endpoint.protocol());
    acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true));
    acceptor_.bind(endpoint);
    acceptor_.listen();
    period_ = client::test::FakeServer(options()).tick_period_s();
    do_accept();
    arm_timer();
    thread_ = std::thread([this] { io_.run(); });
  }
  ~StreamTestServer() {
    io_.stop();
    thread_.join();
  }
  StreamTestServer(const StreamTestServer&) = delete;
  StreamTestServer& operator=(const StreamTestServer&) = delete;

  std::uint16_t port() const { return acceptor_.local_endpoint().port(); }
  int sessions() const { return sessions_.load(); }
  std::uint32_t frames_sent() const { return frames_sent_.load(); }

 private:
  client::test::FakeServerOptions options() const {
    client::test::FakeServerOptions o;
    o.profile_id = profile_id_;
    o.offer_udp = false;  // the viewer falls back to TCP frames; UDP is ClientConnection's own tests' business
    return o;
  }

  static double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }

  void do_accept() {
    acceptor_.async_accept([this](std::error_code ec, asio::ip::tcp::socket s) {
      if (ec) return;
      std::error_code ignored;
      socket_.close(ignored);
      socket_ = std::move(s);
      socket_.set_option(asio::ip::tcp::no_delay(true));
      fake_ = std::make_unique<client::test::FakeServer>(options());
      framer_.reset();
      pending_.clear();
      ++generation_;
      ++sessions_;
      do_read(generation_);
      do_accept();
    });
  }

  void do_read(std::uint64_t generation) {
    socket_.async_read_some(asio::buffer(in_), [this, generation](std::error_code ec, std::size_t n) {
      if (ec || generation != generation_) return;
      std::span<const std::uint8_t> rest(in_.data(), n);
      while (!rest.empty()) {
        const auto r = framer_.feed(rest);
        rest = rest.subspan(r.consumed);
        if (r.status == protocol::TcpFramer::Status::bad) return;
        if (r.status != protocol::TcpFramer::Status::good) break;
        fake_->on_tcp(framer_.message(), now_s());
      }
      flush();
      do_read(generation);
    });
  }

  void arm_timer() {
    timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(period_)));
    timer_.async_wait([this](std::error_code ec) {
      if (ec) return;
      if (fake_) {
        fake_->step();
        ++frames_sent_;
        flush();
      }
      arm_timer();
    });
  }

  void flush() {
    for (auto& bytes : fake_->to_client_tcp) pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    fake_->to_client_tcp.clear();
    fake_->to_client_udp.clear();
    if (writing_ || pending_.empty()) return;
    writing_ = true;
    out_.assign(pending_.begin(), pending_.end());
    pending_.clear();
    asio::async_write(socket_, asio::buffer(out_), [this](std::error_code ec, std::size_t) {
      writing_ = false;
      if (!ec && fake_) flush();
    });
  }

  asio::io_context io_;
  asio::ip::tcp::acceptor acceptor_;
  asio::ip::tcp::socket socket_;
  asio::steady_timer timer_;
  std::uint8_t profile_id_;
  double period_ = 1.0 / 30.0;
  std::unique_ptr<client::test::FakeServer> fake_;
  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 16 * 1024> in_{};
  std::deque<std::uint8_t> pending_;
  protocol::Bytes out_;
  bool writing_ = false;
  std::uint64_t generation_ = 0;
  std::atomic<int> sessions_{0};
  std::atomic<std::uint32_t> frames_sent_{0};
  std::thread thread_;
};

}  // namespace ocean::viewer::test
