// DatagramBatch: a burst larger than one sendmmsg arrives whole and in order; a datagram the kernel
// refuses is counted and does not stop the rest.
#include "datagram_batch.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/udp.hpp>
#include <catch2/catch.hpp>

using namespace ocean::server;

namespace {

SharedBytes numbered(std::uint32_t i, std::size_t size) {
  ocean::protocol::Bytes bytes(size, 0);
  for (std::size_t b = 0; b < 4; ++b) bytes[b] = static_cast<std::uint8_t>(i >> (8 * b));
  return share(std::move(bytes));
}

std::uint32_t number_of(const std::array<std::uint8_t, 2048>& buffer) {
  return buffer[0] | (buffer[1] << 8) | (buffer[2] << 16) | (static_cast<std::uint32_t>(buffer[3]) << 24);
}

}  // namespace

TEST_CASE("DatagramBatch sends a burst of several batches whole and in order", "[datagram_batch]") {
  asio::io_context io;
  asio::ip::udp::socket sender(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  asio::ip::udp::socket receiver(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  receiver.set_option(asio::socket_base::receive_buffer_size(1 << 20));
  const auto to = receiver.local_endpoint();
  DatagramBatch batch;
  constexpr std::uint32_t kCount = 150;  // two full batches and a partial one
  for (std::uint32_t i = 0; i < kCount; ++i) batch.add(numbered(i, 100 + i), to, sender.native_handle());
  batch.flush(sender.native_handle());
  CHECK(batch.sent() == kCount);
  CHECK(batch.dropped() == 0);
  CHECK(batch.calls() == 3);
  std::array<std::uint8_t, 2048> buffer{};
  for (std::uint32_t i = 0; i < kCount; ++i) {
    asio::ip::udp::endpoint from;
    const std::size_t n = receiver.receive_from(asio::buffer(buffer), from);
    REQUIRE(n == 100 + i);
    REQUIRE(number_of(buffer) == i);
  }
}

TEST_CASE("DatagramBatch counts a refused datagram and sends the others", "[datagram_batch]") {
  asio::io_context io;
  asio::ip::udp::socket sender(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  asio::ip::udp::socket receiver(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
  DatagramBatch batch;
  const asio::ip::udp::endpoint v6(asio::ip::make_address("::1"), 9);  // wrong family for an IPv4 socket
  batch.add(numbered(1, 50), receiver.local_endpoint(), sender.native_handle());
  batch.add(numbered(2, 50), v6, sender.native_handle());
  batch.add(numbered(3, 50), receiver.local_endpoint(), sender.native_handle());
  batch.flush(sender.native_handle());
  CHECK(batch.sent() == 2);
  CHECK(batch.dropped() == 1);
  std::array<std::uint8_t, 2048> buffer{};
  asio::ip::udp::endpoint from;
  receiver.receive_from(asio::buffer(buffer), from);
  CHECK(number_of(buffer) == 1);
  receiver.receive_from(asio::buffer(buffer), from);
  CHECK(number_of(buffer) == 3);
}
