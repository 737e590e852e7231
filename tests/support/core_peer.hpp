// CorePeer: the real server session core (SessionCore) in a test's process, with no sockets and
// no clocks: one in-memory stream link, an in-memory UDP socket, and the real simulation producing
// each tick's frames. Client tests talk to it instead of a second, hand-written server, so they
// test the client against the rules the server actually keeps.
#pragma once

#include "core_rig.hpp"
#include "memory_links.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "verify_message.hpp"

#include <memory>
#include <vector>

namespace ocean::test {

class CorePeer {
 public:
  static inline const asio::ip::udp::endpoint kClientUdp{asio::ip::make_address("127.0.0.1"), 40001};

  explicit CorePeer(server::ServerConfig config = core_test_config(),
                    server::SessionCoreOptions options = core_test_options())
      : rig_(std::move(config), options, datagrams_, 7701, 0), link_(std::make_shared<MemoryLink>()) {
    rig_.core().open(link_, CoreRig::at(0.0));
  }

  double tick_period_s() const { return rig_.tick_period_s(); }
  Tick tick() const { return rig_.tick(); }
  std::uint64_t session_id() const { return session_id_; }
  server::SessionCore& core() { return rig_.core(); }
  MemoryLink& link() { return *link_; }

  // Client -> server, as the client's events hand them over.
  void on_tcp(std::span<const std::uint8_t> bytes, double now) {
    observe(bytes, wire::Transport::tcp);
    link_->deliver(bytes, CoreRig::at(now));
  }
  void on_udp(std::span<const std::uint8_t> bytes, double now) {
    observe(bytes, wire::Transport::udp);
    rig_.core().on_datagram(bytes, client_udp, CoreRig::at(now));
  }

  // The next tick's frames reach the core; what it sent lands in to_client_tcp / to_client_udp
  // (with what it sent outside the tick: Welcome, Pong, UdpReady).
  void step(double now) {
    rig_.step(now);
    for (auto& message : link_->take()) {
      if (session_id_ == 0) remember_welcome(message);
      to_client_tcp.push_back(std::move(message));
    }
    for (auto& datagram : datagrams_.take())  // what goes to an address the client left is lost
      if (datagram.to == client_udp) to_client_udp.push_back(std::move(datagram.bytes));
  }

  server::ServerMetrics& metrics() { return rig_.metrics(); }
  const codec::EncodedFrame* sent_frame(Tick tick) const { return rig_.sent_frame(tick); }
  const codec::ModalState* sent_state(Tick tick) const { return rig_.sent_state(tick); }

  // Where the client's datagrams come from (a NAT rebinding changes the port).
  asio::ip::udp::endpoint client_udp = kClientUdp;
  std::vector<protocol::Bytes> to_client_tcp, to_client_udp;
  std::vector<protocol::Ack> acks;
  std::vector<wire::KeyframeReason> keyframe_requests;
  int udp_hellos = 0, set_transport_tcp = 0, pings = 0;

 private:
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

  MemoryDatagrams datagrams_;  // first: the rig's core sends through it
  CoreRig rig_;
  std::shared_ptr<MemoryLink> link_;
  std::uint64_t session_id_ = 0;

 public:
  int& keyframes_sent = rig_.keyframes_sent;
};

}  // namespace ocean::test
