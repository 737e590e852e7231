// DatagramPort: every datagram reaches the handler whole, in order and with its sender; a steady
// stream costs a wake per pause, not per datagram; an oversized datagram arrives truncated to the
// buffer (so it is refused as too large, never read past); after close() nothing more arrives.
#include "datagram_port.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/udp.hpp>
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>
#include <vector>

using namespace ocean::server;
using Clock = std::chrono::steady_clock;

namespace {

struct Received {
  std::uint32_t number;
  std::size_t size;
  asio::ip::udp::endpoint from;
};

struct PortRig {
  PortRig() {
    asio::ip::udp::socket socket(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
    socket.set_option(asio::socket_base::receive_buffer_size(1 << 21));
    socket.non_blocking(true);
    to = socket.local_endpoint();
    port = std::make_unique<DatagramPort>(io, std::move(socket),
                                          [this](std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& from) {
                                            std::uint32_t n = 0;
                                            for (std::size_t b = 0; b < 4 && b < bytes.size(); ++b) n |= std::uint32_t{bytes[b]} << (8 * b);
                                            got.push_back({n, bytes.size(), from});
                                          });
    port->start();
  }
  // Runs the context until `count` datagrams arrived or `seconds` passed.
  void run_until(std::size_t count, double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (got.size() < count && Clock::now() < end) io.run_for(std::chrono::milliseconds(5));
  }
  asio::io_context io;
  asio::ip::udp::endpoint to;
  std::unique_ptr<DatagramPort> port;
  std::vector<Received> got;
};

std::vector<std::uint8_t> numbered_payload(std::uint32_t i, std::size_t size) {
  std::vector<std::uint8_t> bytes(size, 0xAB);
  for (std::size_t b = 0; b < 4; ++b) bytes[b] = static_cast<std::uint8_t>(i >> (8 * b));
  return bytes;
}

}  // namespace

TEST_CASE("DatagramPort hands over a steady stream whole and in order with far fewer wakes than datagrams",
          "[datagram_port]") {
  PortRig rig;
  asio::ip::udp::socket sender(rig.io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  constexpr std::uint32_t kCount = 600;
  // One datagram every 0.1 ms for 60 ms from another thread, as a thousand acking viewers send.
  std::thread feeder([&] {
    const auto start = Clock::now();
    for (std::uint32_t i = 0; i < kCount; ++i) {
      std::this_thread::sleep_until(start + std::chrono::microseconds(100 * i));
      sender.send_to(asio::buffer(numbered_payload(i, 40 + i % 100)), rig.to);
    }
  });
  rig.run_until(kCount, 10.0);
  feeder.join();
  REQUIRE(rig.got.size() == kCount);
  for (std::uint32_t i = 0; i < kCount; ++i) {
    REQUIRE(rig.got[i].number == i);
    REQUIRE(rig.got[i].size == 40 + i % 100);
    REQUIRE(rig.got[i].from == sender.local_endpoint());
  }
  INFO("wakes: " << rig.port->wakes());
  // 60 ms of arrivals with a 1 ms pause after each wake: about 60 wakes; one per datagram was 600.
  CHECK(rig.port->wakes() < kCount / 3);
}

TEST_CASE("DatagramPort reads a lone datagram at once and truncates an oversized one to its buffer",
          "[datagram_port]") {
  PortRig rig;
  asio::ip::udp::socket sender(rig.io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  sender.send_to(asio::buffer(numbered_payload(7, 3000)), rig.to);
  sender.send_to(asio::buffer(numbered_payload(8, 12)), rig.to);
  rig.run_until(2, 5.0);
  REQUIRE(rig.got.size() == 2);
  CHECK(rig.got[0].number == 7);
  CHECK(rig.got[0].size == DatagramPort::kBufferBytes);
  CHECK(rig.got[1].number == 8);
  CHECK(rig.got[1].size == 12);
}

TEST_CASE("DatagramPort delivers nothing after close and lets the context finish", "[datagram_port]") {
  PortRig rig;
  asio::ip::udp::socket sender(rig.io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  sender.send_to(asio::buffer(numbered_payload(1, 10)), rig.to);
  rig.run_until(1, 5.0);
  REQUIRE(rig.got.size() == 1);
  rig.port->close();
  CHECK(!rig.port->is_open());
  std::error_code ignored;
  sender.send_to(asio::buffer(numbered_payload(2, 10)), rig.to, 0, ignored);
  const auto start = Clock::now();
  rig.io.run_for(std::chrono::milliseconds(200));  // returns early once no work is left
  CHECK(rig.got.size() == 1);
  CHECK(Clock::now() - start < std::chrono::milliseconds(150));
}
