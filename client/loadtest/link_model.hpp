// LinkModel: one direction of a simulated network link (the kernel here has no netem).
// Packets enter with send(now) and leave with deliver(now); time is an argument, the
// randomness is seeded, so a run with one seed impairs the same packets the same way.
#pragma once

#include "bottleneck.hpp"
#include "link_spec.hpp"

#include <cstdint>
#include <memory>
#include <queue>
#include <vector>

namespace ocean::loadtest {

struct LinkStats {
  std::uint64_t offered = 0;
  std::uint64_t delivered = 0;
  std::uint64_t lost = 0;          // random loss
  std::uint64_t queue_drops = 0;   // rate limiter's queue was full (shared backlog included)
  std::uint64_t duplicated = 0;
  std::uint64_t reordered = 0;
  std::uint64_t retransmitted = 0;  // messages a lost segment held back (retransmit_loss)
  std::uint64_t bytes_delivered = 0;
};

class LinkModel {
 public:
  // shared: the rate limiter this direction queues behind, shared with other models (a client's
  // TCP and UDP in one direction); null = one of its own at spec.rate_bps. Either way the
  // queue limit is this model's spec.queue_bytes, checked against the shared backlog.
  LinkModel(const LinkSpec& spec, std::uint64_t seed, std::shared_ptr<Bottleneck> shared = nullptr);

  // Offers one packet to the link at time now (seconds). It may be lost, dropped by the full
  // queue, delayed, reordered or duplicated.
  void send(std::vector<std::uint8_t> bytes, double now);

  // Calls on_packet(std::vector<uint8_t>&&) for every packet due by now, in delivery order.
  template <typename OnPacket>
  void deliver(double now, OnPacket&& on_packet) {
    while (!pending_.empty() && pending_.top().due <= now) {
      InFlight p = std::move(const_cast<InFlight&>(pending_.top()));
      pending_.pop();
      ++stats_.delivered;
      stats_.bytes_delivered += p.bytes.size();
      on_packet(std::move(p.bytes));
    }
  }

  // Time of the next delivery, or a negative number when nothing is in flight.
  double next_due() const { return pending_.empty() ? -1.0 : pending_.top().due; }
  std::size_t in_flight() const { return pending_.size(); }
  const LinkStats& stats() const { return stats_; }
  const LinkSpec& spec() const { return spec_; }

 private:
  struct InFlight {
    double due;
    std::uint64_t order;  // ties keep sending order
    std::vector<std::uint8_t> bytes;
    bool operator>(const InFlight& o) const { return due != o.due ? due > o.due : order > o.order; }
  };

  double uniform();  // [0, 1)
  void schedule(std::vector<std::uint8_t> bytes, double due);

  LinkSpec spec_;
  std::uint64_t rng_;
  std::uint64_t order_ = 0;
  std::shared_ptr<Bottleneck> bottleneck_;  // null = no rate limit
  double last_in_order_ = 0.0;   // FIFO: an in-order packet never overtakes an earlier one
  LinkStats stats_;
  std::priority_queue<InFlight, std::vector<InFlight>, std::greater<>> pending_;
};

}  // namespace ocean::loadtest
