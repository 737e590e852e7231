// PacketLink: one direction of an impaired link placed between a ClientConnection's sockets and its
// ClientSession, so a load test can dial in rate, delay, jitter and loss in-process (no netem here).
// Any type with send(bytes, now) / deliver(now, cb) / next_due() (loadtest::LinkModel) fits the adapter.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace ocean::client {

class PacketLink {
 public:
  using OnPacket = std::function<void(std::vector<std::uint8_t>&&)>;
  virtual ~PacketLink() = default;
  virtual void send(std::vector<std::uint8_t> bytes, double now) = 0;
  virtual void deliver(double now, const OnPacket& on_packet) = 0;
  virtual double next_due() const = 0;  // < 0: nothing in flight
};

template <typename Link>
class PacketLinkAdapter final : public PacketLink {
 public:
  template <typename... Args>
  explicit PacketLinkAdapter(Args&&... args) : link_(std::forward<Args>(args)...) {}
  void send(std::vector<std::uint8_t> bytes, double now) override { link_.send(std::move(bytes), now); }
  void deliver(double now, const OnPacket& on_packet) override {
    link_.deliver(now, [&](std::vector<std::uint8_t>&& bytes) { on_packet(std::move(bytes)); });
  }
  double next_due() const override { return link_.next_due(); }
  Link& link() { return link_; }
  const Link& link() const { return link_; }

 private:
  Link link_;
};

// The four directions of one client. Any may be null (that direction is unimpaired).
// TCP carries whole messages in order: give tcp_up / tcp_down a link with rate and delay but no
// loss, reordering or duplication (TCP's retransmissions show up as delay, not loss: model a
// lost segment as one extra RTO of delay). A TCP link that drops a message breaks the session.
struct ConnectionLinks {
  std::unique_ptr<PacketLink> tcp_up, tcp_down, udp_up, udp_down;
};

}  // namespace ocean::client
