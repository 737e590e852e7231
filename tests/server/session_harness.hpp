// SessionHarness: a Server with its SessionHub running on a thread over loopback (ephemeral ports),
// recording what the hub sent each session so tests compare client reconstructions with it.
#pragma once

#include "server.hpp"
#include "server_log.hpp"
#include "session_hub.hpp"
#include "session_test_client.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <future>
#include <map>
#include <mutex>

namespace ocean::server::test {

inline ServerConfig session_test_config(int tick_rate_hz = 30) {
  ServerConfig config;
  config.listen = {"127.0.0.1", 0};
  config.metrics_listen = std::nullopt;
  config.scene.size_x = config.scene.size_z = 64;
  config.scene.patch_x_m = config.scene.patch_z_m = 64.0;
  config.profiles = {"mobile", "lite"};
  config.tick_rate_hz = tick_rate_hz;
  config.log_level = "warn";
  set_log_level(config.log_level);
  return config;
}

class SessionHarness {
 public:
  explicit SessionHarness(ServerConfig config, SessionCoreOptions options = {})
      : server_(std::move(config)), hub_(server_, options) {
    hub_.core().set_frame_observer([this](std::uint64_t session, const SharedFrame& frame) {
      std::lock_guard lock(mutex_);
      sent_[{session, frame.encoded->reconstruction.tick}] = frame.encoded->reconstruction.height;
      recorded_.notify_all();
    });
    hub_.core().set_tick_observer([this](const CoreTickStats& stats) {
      std::lock_guard lock(mutex_);
      ticks_.push_back(stats);
    });
    done_ = std::async(std::launch::async, [this] { server_.run(); });
  }
  ~SessionHarness() { stop(); }
  void stop() {
    if (!done_.valid()) return;
    server_.stop();
    done_.wait();
    done_ = {};
  }

  Server& server() { return server_; }
  SessionHub& hub() { return hub_; }  // read only after stop(): the hub lives on the network thread
  // A client on the WebSocket port (--ws-listen), sending this Origin ("" = none).
  std::unique_ptr<SessionTestClient> ws_client(const std::string& origin = "") {
    return std::make_unique<SessionTestClient>(server_.ws_port().value(), server_.udp_port(), 0, origin);
  }
  std::unique_ptr<SessionTestClient> client(int receive_buffer_bytes = 0) {
    return std::make_unique<SessionTestClient>(server_.tcp_port(), server_.udp_port(), receive_buffer_bytes);
  }
  std::vector<CoreTickStats> ticks() {
    std::lock_guard lock(mutex_);
    return ticks_;
  }
  // What the encoder said session `session` shows at `tick` (empty if nothing was sent).
  std::vector<float> sent_height(std::uint64_t session, Tick tick) {
    std::unique_lock lock(mutex_);
    const auto found = await_sent(lock, session, tick);
    return found == sent_.end() ? std::vector<float>{} : found->second;
  }
  // Every tick the client completed equals, bit for bit, what the encoder said it would show.
  void check_reconstructions(const SessionTestClient& client) {
    REQUIRE(client.welcome);
    std::unique_lock lock(mutex_);
    for (const auto& [tick, heights] : client.completed_heights) {
      const auto found = await_sent(lock, client.welcome->session_id, tick);
      REQUIRE(found != sent_.end());
      REQUIRE(found->second == heights);
    }
  }

 private:
  Server server_;
  SessionHub hub_;
  std::future<void> done_;
  std::mutex mutex_;
  std::condition_variable recorded_;
  using Sent = std::map<std::pair<std::uint64_t, Tick>, std::vector<float>>;
  Sent sent_;
  std::vector<CoreTickStats> ticks_;

  // The observer runs on the network thread after the frame went to the links, so a client may
  // have completed it first (seen under TSan): a missing record gets a moment to arrive.
  Sent::const_iterator await_sent(std::unique_lock<std::mutex>& lock, std::uint64_t session, Tick tick) {
    recorded_.wait_for(lock, std::chrono::seconds(2), [&] { return sent_.count({session, tick}) > 0; });
    return sent_.find({session, tick});
  }
};

// Pumps every client until the condition holds; false after `limit` (generous: a loaded machine).
inline bool pump_until(const std::vector<SessionTestClient*>& clients, const std::function<bool()>& condition,
                       std::chrono::milliseconds limit = std::chrono::seconds(20)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  for (;;) {
    for (SessionTestClient* c : clients) {
      c->pump();
      c->prove_udp_if_due();
    }
    if (condition()) return true;
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace ocean::server::test
