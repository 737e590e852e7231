// CorePeer: the real server session core (SessionCore) in a test's process, with no sockets and
// no clocks: one in-memory stream link, an in-memory UDP socket, and the real simulation producing
// each tick's frames. Client tests talk to it instead of a second, hand-written server, so they
// test the client against the rules the server actually keeps.
#pragma once

#include "frame_producer.hpp"
#include "memory_links.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "metrics.hpp"
#include "server_log.hpp"
#include "session_core.hpp"
#include "verify_message.hpp"

#include <map>
#include <stdexcept>
#include <memory>
#include <vector>

namespace ocean::test {

// A small scene (64 m, 64^2) streamed as the mobile profile at 30 Hz.
inline server::ServerConfig core_peer_config(std::string profile = "mobile") {
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
inline server::SessionCoreOptions core_peer_options() {
  server::SessionCoreOptions options;
  options.key_period_s = 0.0;
  options.baseline_align_frames = 1;
  return options;
}

class CorePeer {
 public:
  static inline const asio::ip::udp::endpoint kClientUdp{asio::ip::make_address("127.0.0.1"), 40001};

  explicit CorePeer(server::ServerConfig config = core_peer_config(),
                    server::SessionCoreOptions options = core_peer_options())
      : config_(std::move(config)),
        schedule_(schedule_of(config_)),
        metrics_(registry_),
        cookie_key_(server::random_cookie_key()),
        producer_(schedule_, profiles_of(config_)),
        core_(server::SessionCoreHost{config_, schedule_, metrics_, cookie_key_, datagrams_, 7701,
                                      [this](const sim::SceneParams& scene, std::int64_t from) {
                                        producer_.override_scene(scene, from);
                                      }},
              options, 0) {
    core_.set_frame_observer([this](std::uint64_t, const server::SharedFrame& frame) {
      sent_[frame.encoded->reconstruction.tick] = frame.encoded;
      if (frame.encoded->key) ++keyframes_sent;
    });
    server::set_log_level(config_.log_level);
    link_ = std::make_shared<MemoryLink>();
    core_.open(link_, at(0.0));
  }

  double tick_period_s() const { return 1.0 / config_.tick_rate_hz; }
  Tick tick() const { return tick_; }
  std::uint64_t session_id() const { return session_id_; }
  server::SessionCore& core() { return core_; }
  MemoryLink& link() { return *link_; }

  // Client -> server, as the client's events hand them over.
  void on_tcp(std::span<const std::uint8_t> bytes, double now) {
    observe(bytes, wire::Transport::tcp);
    link_->deliver(bytes, at(now));
  }
  void on_udp(std::span<const std::uint8_t> bytes, double now) {
    observe(bytes, wire::Transport::udp);
    core_.on_datagram(bytes, kClientUdp, at(now));
  }

  // The next tick's frames reach the core; what it sent lands in to_client_tcp / to_client_udp.
  void step(double now) {
    ++tick_;
    core_.on_frames(producer_.produce(static_cast<std::int64_t>(tick_), tick_ * tick_period_s()), at(now));
    collect();
  }
  // Messages the core sends outside a tick (Welcome, Pong, UdpReady) appear after this.
  void collect() {
    for (auto& message : link_->take()) {
      if (session_id_ == 0) remember_welcome(message);
      to_client_tcp.push_back(std::move(message));
    }
    for (auto& datagram : datagrams_.take()) to_client_udp.push_back(std::move(datagram.bytes));
  }

  // What the encoder says the client shows for `tick` once complete (null if never sent).
  const codec::EncodedFrame* sent_frame(Tick tick) const {
    const auto found = sent_.find(tick);
    return found == sent_.end() ? nullptr : found->second.get();
  }
  const codec::ModalState* sent_state(Tick tick) const {
    const auto found = sent_.find(tick);
    return found == sent_.end() ? nullptr : core_.streams().front()->state(found->second->id);
  }

  std::vector<protocol::Bytes> to_client_tcp, to_client_udp;
  std::vector<protocol::Ack> acks;
  std::vector<wire::KeyframeReason> keyframe_requests;
  int udp_hellos = 0, set_transport_tcp = 0, keyframes_sent = 0, pings = 0;

 private:
  static server::Instant at(double now) { return server::Instant{now, static_cast<std::int64_t>(now * 1000.0)}; }

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

  // Counts what the client asked for; the core itself decides what to do with it.
  void observe(std::span<const std::uint8_t> bytes, wire::Transport transport) {
    protocol::Bytes copy(bytes.begin(), bytes.end());  // aligned
    const auto verified = protocol::verify_message(copy, {protocol::Sender::client, transport});
    if (!verified) return;
    const protocol::AnyMessage message = protocol::decode(*verified.message);
    if (std::holds_alternative<protocol::UdpHello>(message)) ++udp_hellos;
    if (const auto* ack = std::get_if<protocol::Ack>(&message)) acks.push_back(*ack);
    if (const auto* request = std::get_if<protocol::KeyframeRequest>(&message)) keyframe_requests.push_back(request->reason);
    if (const auto* set = std::get_if<protocol::SetTransport>(&message); set && set->transport == wire::Transport::tcp)
      ++set_transport_tcp;
    if (std::holds_alternative<protocol::Ping>(message)) ++pings;
  }

  void remember_welcome(const protocol::Bytes& message) {
    protocol::Bytes copy = message;
    const auto verified = protocol::verify_message(copy, {protocol::Sender::server, wire::Transport::tcp});
    if (verified && verified.message->body_type() == wire::Body::Welcome)
      session_id_ = verified.message->body_as_Welcome()->session_id();
  }

  server::ServerConfig config_;
  server::SceneSchedule schedule_;
  server::MetricsRegistry registry_;
  server::ServerMetrics metrics_;
  server::CookieKey cookie_key_;
  MemoryDatagrams datagrams_;
  server::FrameProducer producer_;
  server::SessionCore core_;
  std::shared_ptr<MemoryLink> link_;
  Tick tick_ = 0;
  std::uint64_t session_id_ = 0;
  std::map<Tick, std::shared_ptr<const codec::EncodedFrame>> sent_;
};

}  // namespace ocean::test
