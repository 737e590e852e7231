// A WebSocket client's side of RFC 6455 for tests, by hand on purpose: tests must also send what
// no library would (oversized, text and broken frames). The upgrade request, masked client frames,
// and a deframer for the server's unmasked frames.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ocean::test {

inline std::string ws_upgrade_request(std::uint16_t port, const std::string& origin = {}) {
  std::string request = "GET /ocean HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                        "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n";
  if (!origin.empty()) request += "Origin: " + origin + "\r\n";
  return request + "\r\n";
}

enum WsOpcode : std::uint8_t { ws_text = 1, ws_binary = 2, ws_close = 8, ws_ping = 9, ws_pong = 10 };

// One final, masked client frame.
inline std::vector<std::uint8_t> ws_client_frame(std::uint8_t opcode, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> frame{static_cast<std::uint8_t>(0x80 | opcode)};
  const std::uint64_t n = payload.size();
  if (n < 126) {
    frame.push_back(static_cast<std::uint8_t>(0x80 | n));
  } else if (n <= 0xFFFF) {
    frame.push_back(0x80 | 126);
    frame.push_back(static_cast<std::uint8_t>(n >> 8));
    frame.push_back(static_cast<std::uint8_t>(n));
  } else {
    frame.push_back(0x80 | 127);
    for (int shift = 56; shift >= 0; shift -= 8) frame.push_back(static_cast<std::uint8_t>(n >> shift));
  }
  const std::uint8_t mask[4] = {0x37, 0xfa, 0x21, 0x3d};
  frame.insert(frame.end(), mask, mask + 4);
  for (std::size_t i = 0; i < payload.size(); ++i) frame.push_back(payload[i] ^ mask[i % 4]);
  return frame;
}

// The server's frames, from the byte stream after the HTTP response.
class WsDeframer {
 public:
  struct Frame {
    std::uint8_t opcode = 0;
    std::vector<std::uint8_t> payload;
  };
  void feed(std::span<const std::uint8_t> bytes) { buffer_.insert(buffer_.end(), bytes.begin(), bytes.end()); }
  // The next whole frame, if one has arrived.
  std::optional<Frame> next() {
    if (buffer_.size() < 2) return std::nullopt;
    std::size_t at = 2;
    std::uint64_t n = buffer_[1] & 0x7f;
    if (n == 126 || n == 127) {
      const std::size_t bytes = n == 126 ? 2 : 8;
      if (buffer_.size() < 2 + bytes) return std::nullopt;
      n = 0;
      for (std::size_t i = 0; i < bytes; ++i) n = (n << 8) | buffer_[2 + i];
      at += bytes;
    }
    if (buffer_[1] & 0x80) at += 4;  // a server never masks; skipped if it did
    if (buffer_.size() < at + n) return std::nullopt;
    Frame frame{static_cast<std::uint8_t>(buffer_[0] & 0x0f),
                std::vector<std::uint8_t>(buffer_.begin() + static_cast<std::ptrdiff_t>(at),
                                          buffer_.begin() + static_cast<std::ptrdiff_t>(at + n))};
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at + n));
    return frame;
  }

 private:
  std::vector<std::uint8_t> buffer_;
};

}  // namespace ocean::test
