#include "link_model.hpp"

#include <catch2/catch.hpp>

#include <cstring>

using namespace ocean::loadtest;

namespace {
LinkSpec spec_of(const char* text) {
  auto r = parse_link_spec(text);
  REQUIRE(r.error.empty());
  return r.spec;
}

std::vector<std::uint8_t> numbered(std::uint32_t n, std::size_t size = 100) {
  std::vector<std::uint8_t> b(size, 0);
  std::memcpy(b.data(), &n, sizeof n);
  return b;
}

// What client_links.cpp gives TCP: rate and delay, a queue that never drops.
LinkSpec tcp_view_for_test() {
  LinkSpec t = spec_of("rate=80kbit,delay=10ms");
  t.queue_bytes = 0xFFFFFFFFu;
  return t;
}

std::uint32_t number_of(const std::vector<std::uint8_t>& b) {
  std::uint32_t n = 0;
  std::memcpy(&n, b.data(), sizeof n);
  return n;
}
}  // namespace

TEST_CASE("link model: an unimpaired link delivers everything at once, in order") {
  LinkModel link(LinkSpec{}, 1);
  for (std::uint32_t i = 0; i < 100; ++i) link.send(numbered(i), 0.0);
  std::uint32_t expect = 0;
  link.deliver(0.0, [&](std::vector<std::uint8_t>&& b) { CHECK(number_of(b) == expect++); });
  CHECK(expect == 100);
}

TEST_CASE("link model: delay and jitter bound the arrival time, order is kept") {
  LinkModel link(spec_of("delay=80ms,jitter=20ms"), 7);
  for (std::uint32_t i = 0; i < 1000; ++i) link.send(numbered(i), i * 0.001);
  double t = 0;
  std::uint32_t expect = 0;
  while (link.in_flight()) {
    t += 0.0005;
    link.deliver(t, [&](std::vector<std::uint8_t>&& b) {
      const std::uint32_t n = number_of(b);
      CHECK(n == expect++);
      CHECK(t - n * 0.001 >= 0.060 - 1e-9);
      CHECK(t - n * 0.001 <= 0.100 + 0.0005 + 0.020);  // FIFO may hold a packet behind a late one
    });
  }
  CHECK(expect == 1000);
}

TEST_CASE("link model: the rate limits throughput and the queue bounds it") {
  // 100-byte packets offered at 1000/s (800 kbit/s) into a 256 kbit/s link with a 4 kB queue.
  LinkModel link(spec_of("rate=256kbit,queue=4kB"), 3);
  for (int i = 0; i < 2000; ++i) link.send(numbered(i), i * 0.001);
  std::uint64_t bytes = 0;
  link.deliver(2.0, [&](std::vector<std::uint8_t>&& b) { bytes += b.size(); });
  // At most rate * time plus what fits in the queue at the end.
  CHECK(bytes * 8.0 <= 256000 * 2.0 + 100 * 8);
  CHECK(bytes * 8.0 >= 256000 * 2.0 - 4096 * 8 - 100 * 8);
  CHECK(link.stats().queue_drops > 0);
  CHECK(link.in_flight() * 100 <= 4096 + 100);
}

TEST_CASE("link model: loss, duplication and reordering happen at their rates") {
  LinkModel link(spec_of("delay=50ms,jitter=10ms,loss=5%,dup=2%,reorder=3%"), 11);
  const int n = 20000;
  for (int i = 0; i < n; ++i) link.send(numbered(i), i * 0.001);
  int inversions = 0;
  std::uint32_t last = 0;
  std::uint64_t got = 0;
  link.deliver(1e9, [&](std::vector<std::uint8_t>&& b) {
    const std::uint32_t k = number_of(b);
    if (got && k < last) ++inversions;
    last = k;
    ++got;
  });
  const auto& s = link.stats();
  CHECK(s.lost == Approx(0.05 * n).epsilon(0.15));
  CHECK(s.duplicated == Approx(0.02 * (n - s.lost)).epsilon(0.2));
  CHECK(s.reordered == Approx(0.03 * (n - s.lost)).epsilon(0.2));
  CHECK(got == n - s.lost + s.duplicated);
  CHECK(inversions > 0);
}

TEST_CASE("link model: one seed impairs the same packets the same way") {
  auto run = [](std::uint64_t seed) {
    LinkModel link(spec_of("delay=30ms,jitter=10ms,loss=10%,reorder=5%"), seed);
    for (std::uint32_t i = 0; i < 500; ++i) link.send(numbered(i), i * 0.002);
    std::vector<std::uint32_t> order;
    link.deliver(1e9, [&](std::vector<std::uint8_t>&& b) { order.push_back(number_of(b)); });
    return order;
  };
  CHECK(run(5) == run(5));
  CHECK(run(5) != run(6));
}

TEST_CASE("link model: models sharing a bottleneck queue behind each other's bytes") {
  // 80 kbit/s = 10 kB/s: a 10 kB TCP message holds the link for 1 s, and a datagram sent just after
  // it leaves only then, however empty its own model is.
  auto down = std::make_shared<Bottleneck>(80000);
  LinkModel tcp(tcp_view_for_test(), 1, down);
  LinkModel udp(spec_of("rate=80kbit,delay=10ms"), 2, down);
  tcp.send(numbered(1, 10000), 0.0);
  udp.send(numbered(2, 100), 0.001);
  CHECK(tcp.next_due() == Approx(1.0 + 0.010));
  CHECK(udp.next_due() == Approx(1.0 + 0.010 + 100 * 8.0 / 80000));
  CHECK(down->backlog_bytes(0.5) == Approx(5100).margin(1));
}

TEST_CASE("link model: a shared backlog makes the UDP queue drop, never the TCP one") {
  auto down = std::make_shared<Bottleneck>(80000);
  LinkModel tcp(tcp_view_for_test(), 1, down);
  LinkModel udp(spec_of("rate=80kbit,queue=4kB"), 2, down);
  tcp.send(numbered(1, 8000), 0.0);
  udp.send(numbered(2, 100), 0.0);  // 8 kB ahead of it: over its 4 kB queue
  CHECK(udp.stats().queue_drops == 1);
  tcp.send(numbered(3, 8000), 0.0);  // TCP's queue is unbounded
  CHECK(tcp.stats().queue_drops == 0);
  CHECK(tcp.in_flight() == 2);
  udp.send(numbered(4, 100), 1.5);  // 16 kB queued, 15 kB gone by 1.5 s: 1 kB ahead, it fits
  CHECK(udp.stats().queue_drops == 1);
  CHECK(udp.next_due() == Approx(1.6 + 0.01).margin(1e-6));
}
