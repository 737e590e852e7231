// StreamTestServer: a streaming server for the viewer tests - the real server core behind loopback
// sockets (tests/support LoopbackCore), stepped at the server's tick rate on its own thread.
// Destroying it and making another on the same port is a server restart.
#pragma once

#include "loopback_core.hpp"

#include <asio/io_context.hpp>

#include <memory>
#include <thread>

namespace ocean::viewer::test {

class StreamTestServer {
 public:
  // profile: "mobile" (64 x 64 at 30 Hz) or "lite" (32 x 32 at 15 Hz).
  StreamTestServer(std::uint16_t port, const std::string& profile)
      : core_(std::make_unique<ocean::test::LoopbackCore>(io_, port, 1, ocean::test::core_test_config(profile), 1.0 / 30.0)),
        port_(core_->port()),
        thread_([this] { io_.run(); }) {}
  ~StreamTestServer() {
    io_.stop();
    thread_.join();  // then core_ closes its sockets with nothing running beside it
  }
  StreamTestServer(const StreamTestServer&) = delete;
  StreamTestServer& operator=(const StreamTestServer&) = delete;

  std::uint16_t port() const { return port_; }
  int sessions() const { return core_->hellos(); }  // sessions welcomed

 private:
  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_ = asio::make_work_guard(io_);
  std::unique_ptr<ocean::test::LoopbackCore> core_;
  std::uint16_t port_;
  std::thread thread_;
};

}  // namespace ocean::viewer::test
