// CoreRig: everything a SessionCore needs from a server except its sockets - config, schedule,
// metrics, cookie key and the real simulation producing each tick's frames - and the core itself,
// recording what it sent. CorePeer (in memory) and LoopbackCore (real loopback sockets) add links.
#pragma once

#include "frame_producer.hpp"
#include "metrics.hpp"
#include "server_log.hpp"
#include "session_core.hpp"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ocean::test {

// A small scene (64 m, 64^2) streamed as the mobile profile at 30 Hz.
inline server::ServerConfig core_test_config(std::string profile = "mobile") {
  server::ServerConfig config;
  config.scene.size_x = config.scene.size_z = 64;
  config.scene.patch_x_m = config.scene.patch_z_m = 64.0;
  config.profiles = {std::move(profile)};
  config.tick_rate_hz = 30;
  config.log_level = "warn";
  return config;
}

// Keys at the next frame tick (not on a shared grid) and baselines on every frame: what a lone
// client sees of the server, without the fan-out's waits that only pay with many clients.
inline server::SessionCoreOptions core_test_options() {
  server::SessionCoreOptions options;
  options.key_period_s = 0.0;
  options.baseline_align_frames = 1;
  return options;
}

class CoreRig {
 public:
  CoreRig(server::ServerConfig config, server::SessionCoreOptions options, server::DatagramSocket& datagrams,
          std::uint16_t udp_port, Tick first_tick)
      : config_(std::move(config)),
        schedule_(schedule_of(config_)),
        metrics_(registry_),
        cookie_key_(server::random_cookie_key()),
        producer_(schedule_, profiles_of(config_)),
        tick_(first_tick),
        core_(server::SessionCoreHost{config_, schedule_, metrics_, cookie_key_, datagrams, udp_port,
                                      [this](const model::SceneParams& scene, std::int64_t from) {
                                        producer_.override_scene(scene, from);
                                      }},
              options, first_tick) {
    server::set_log_level(config_.log_level);
    core_.set_frame_observer([this](std::uint64_t, const server::SharedFrame& frame) {
      sent_[frame.encoded->reconstruction.tick] = frame.encoded;
      if (frame.encoded->key) ++keyframes_sent;
    });
  }

  static server::Instant at(double now) { return server::Instant{now, static_cast<std::int64_t>(now * 1000.0)}; }

  double tick_period_s() const { return 1.0 / config_.tick_rate_hz; }
  Tick tick() const { return tick_; }
  server::SessionCore& core() { return core_; }
  server::ServerMetrics& metrics() { return metrics_; }

  // The next tick's frames reach the core.
  void step(double now) {
    ++tick_;
    core_.on_frames(producer_.produce(static_cast<std::int64_t>(tick_), static_cast<double>(tick_) * tick_period_s()), at(now));
  }

  // What the encoder says a client shows for `tick` once complete (null if never sent).
  const codec::EncodedFrame* sent_frame(Tick tick) const {
    const auto found = sent_.find(tick);
    return found == sent_.end() ? nullptr : found->second.get();
  }
  const codec::ModalState* sent_state(Tick tick) const {
    const auto found = sent_.find(tick);
    return found == sent_.end() ? nullptr : core_.streams().front()->state(found->second->id);
  }

  int keyframes_sent = 0;

 private:
  static server::SceneSchedule schedule_of(const server::ServerConfig& config) {
    std::string error;
    server::SceneSchedule schedule = server::make_schedule(config, error);
    if (!error.empty()) throw std::invalid_argument(error);
    return schedule;
  }

  static std::vector<const Profile*> profiles_of(const server::ServerConfig& config) {
    std::vector<const Profile*> profiles;
    for (const std::string& name : config.profiles) profiles.push_back(find_profile(std::string_view(name)));
    return profiles;
  }

  server::ServerConfig config_;
  server::SceneSchedule schedule_;
  server::MetricsRegistry registry_;
  server::ServerMetrics metrics_;
  server::CookieKey cookie_key_;
  server::FrameProducer producer_;
  Tick tick_;
  server::SessionCore core_;
  std::map<Tick, std::shared_ptr<const codec::EncodedFrame>> sent_;
};

}  // namespace ocean::test
