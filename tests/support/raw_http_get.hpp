// raw_http_get: one blocking HTTP/1.1 GET over loopback, returning the whole response - status
// line, headers and body - as the server wrote it before closing ("" when it closed at once).
#pragma once

#include <asio/connect.hpp>
#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/read.hpp>
#include <asio/write.hpp>

#include <cstdint>
#include <string>

namespace ocean::server::test {

inline std::string raw_http_get(std::uint16_t port, const std::string& target) {
  asio::io_context context;
  asio::ip::tcp::socket socket(context);
  socket.connect({asio::ip::make_address("127.0.0.1"), port});
  asio::write(socket, asio::buffer("GET " + target + " HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  std::string response;
  std::error_code error;
  asio::read(socket, asio::dynamic_buffer(response), error);
  return response;
}

}  // namespace ocean::server::test
