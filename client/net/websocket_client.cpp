#include "websocket_client.hpp"

#include <openssl/evp.h>
#include <openssl/sha.h>

#include <algorithm>
#include <cctype>

namespace ocean::client {

namespace {

constexpr const char* kAcceptGuid = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";  // RFC 6455 1.3
constexpr std::size_t kMaxAnswerBytes = 8192;

std::string base64(const unsigned char* data, std::size_t size) {
  std::string out(4 * ((size + 2) / 3), '\0');
  EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()), data, static_cast<int>(size));
  return out;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The value of header `name` (lower case) in an HTTP head, or "" when absent.
std::string header(const std::string& head, const std::string& name) {
  const std::string low = lower(head);
  const std::size_t at = low.find("\r\n" + name + ":");
  if (at == std::string::npos) return {};
  std::size_t begin = at + 3 + name.size();
  const std::size_t end = head.find("\r\n", begin);
  while (begin < end && (head[begin] == ' ' || head[begin] == '\t')) ++begin;
  std::size_t last = end;
  while (last > begin && (head[last - 1] == ' ' || head[last - 1] == '\t')) --last;
  return head.substr(begin, last - begin);
}

}  // namespace

WebSocketClient::WebSocketClient(std::uint64_t seed, std::size_t max_message_bytes)
    : random_(seed), max_message_bytes_(max_message_bytes) {}

std::string WebSocketClient::upgrade_request(const std::string& host, const std::string& port) {
  open_ = in_message_ = false;
  buffer_.clear();
  message_.clear();
  unsigned char nonce[16];
  for (unsigned char& b : nonce) b = static_cast<unsigned char>(random_());
  const std::string key = base64(nonce, sizeof nonce);
  expected_accept_ = accept_for(key);
  const std::string authority = host.find(':') != std::string::npos ? "[" + host + "]:" + port : host + ":" + port;
  return "GET / HTTP/1.1\r\nHost: " + authority +
         "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: " + key +
         "\r\nSec-WebSocket-Version: 13\r\n\r\n";
}

std::string WebSocketClient::accept_for(const std::string& key) {
  const std::string input = key + kAcceptGuid;
  unsigned char digest[SHA_DIGEST_LENGTH];
  SHA1(reinterpret_cast<const unsigned char*>(input.data()), input.size(), digest);
  return base64(digest, sizeof digest);
}

std::string WebSocketClient::feed(std::span<const std::uint8_t> bytes,
                                  const std::function<void(std::span<const std::uint8_t>)>& on_message,
                                  const std::function<void(std::vector<std::uint8_t>)>& on_reply) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  // The answer alone: frames behind it wait for the next call, after the caller has seen open().
  if (!open_) return read_answer();
  return read_frames(on_message, on_reply);
}

std::string WebSocketClient::read_answer() {
  const std::string text(buffer_.begin(), buffer_.end());
  const std::size_t end = text.find("\r\n\r\n");
  if (end == std::string::npos)
    return buffer_.size() > kMaxAnswerBytes ? "WebSocket upgrade: no answer within " + std::to_string(kMaxAnswerBytes) + " bytes"
                                            : std::string();
  const std::string head = text.substr(0, end + 2);
  const std::string status = head.substr(0, head.find("\r\n"));
  if (status.rfind("HTTP/1.1 101", 0) != 0) return "WebSocket upgrade refused: " + status;
  if (lower(header(head, "upgrade")) != "websocket") return "WebSocket upgrade: the answer upgrades to something else";
  if (header(head, "sec-websocket-accept") != expected_accept_)
    return "WebSocket upgrade: Sec-WebSocket-Accept does not answer the key";
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(end + 4));
  open_ = true;
  return {};
}

std::string WebSocketClient::read_frames(const std::function<void(std::span<const std::uint8_t>)>& on_message,
                                         const std::function<void(std::vector<std::uint8_t>)>& on_reply) {
  std::size_t at = 0;
  std::string error;
  while (error.empty()) {
    const std::size_t left = buffer_.size() - at;
    if (left < 2) break;
    const std::uint8_t* p = buffer_.data() + at;
    const bool final = p[0] & 0x80;
    const std::uint8_t opcode = p[0] & 0x0f;
    std::size_t head = 2;
    std::uint64_t n = p[1] & 0x7f;
    if (p[0] & 0x70) {
      error = "WebSocket: a frame with reserved bits set";
      break;
    }
    if (p[1] & 0x80) {
      error = "WebSocket: the server masked a frame";
      break;
    }
    if (n >= 126) {
      head += n == 126 ? 2 : 8;
      if (left < head) break;
      n = 0;
      for (std::size_t i = 2; i < head; ++i) n = (n << 8) | p[i];
    }
    if (n > max_message_bytes_ + 16) {
      error = "WebSocket: a frame of " + std::to_string(n) + " bytes, over the message limit";
      break;
    }
    if (left < head + n) break;
    const std::span<const std::uint8_t> payload(p + head, static_cast<std::size_t>(n));
    at += head + static_cast<std::size_t>(n);
    if (opcode == 9) {  // Ping: the same payload back
      on_reply(frame(payload, 10));
    } else if (opcode == 10) {
      // a Pong: nothing to do
    } else if (opcode == 8) {
      const int code = payload.size() >= 2 ? payload[0] << 8 | payload[1] : 1005;
      error = "WebSocket closed by the server (" + std::to_string(code) + ")";
    } else if (opcode == 1 || (opcode == 0 && !in_message_) || (opcode == 2 && in_message_) || opcode > 2) {
      error = "WebSocket: unexpected frame (opcode " + std::to_string(opcode) + ")";
    } else {
      if (opcode == 2 && final) {
        on_message(payload);
        continue;
      }
      message_.insert(message_.end(), payload.begin(), payload.end());
      in_message_ = !final;
      if (message_.size() > max_message_bytes_) error = "WebSocket: a message over the limit";
      else if (final) {
        on_message(message_);
        message_.clear();
      }
    }
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at));
  return error;
}

std::vector<std::uint8_t> WebSocketClient::frame(std::span<const std::uint8_t> message, std::uint8_t opcode) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(0x80 | opcode)};
  const std::uint64_t n = message.size();
  if (n < 126) {
    out.push_back(static_cast<std::uint8_t>(0x80 | n));
  } else if (n <= 0xFFFF) {
    out.push_back(0x80 | 126);
    out.push_back(static_cast<std::uint8_t>(n >> 8));
    out.push_back(static_cast<std::uint8_t>(n));
  } else {
    out.push_back(0x80 | 127);
    for (int shift = 56; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(n >> shift));
  }
  const std::uint64_t bits = random_();
  const std::uint8_t mask[4] = {static_cast<std::uint8_t>(bits), static_cast<std::uint8_t>(bits >> 8),
                                static_cast<std::uint8_t>(bits >> 16), static_cast<std::uint8_t>(bits >> 24)};
  out.insert(out.end(), mask, mask + 4);
  const std::size_t start = out.size();
  out.resize(start + message.size());
  for (std::size_t i = 0; i < message.size(); ++i) out[start + i] = message[i] ^ mask[i % 4];
  return out;
}

}  // namespace ocean::client
