// WebSocketClient: the upgrade's key and its answer (RFC 6455's own example key), masked frames
// out, whole messages in whatever the byte boundaries, and every way a server's bytes end it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "websocket_client.hpp"

using ocean::client::WebSocketClient;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes ws_bytes_of(const std::string& text) { return Bytes(text.begin(), text.end()); }

// The Sec-WebSocket-Key of a request.
std::string ws_key_of(const std::string& request) {
  const std::size_t at = request.find("Sec-WebSocket-Key: ") + 19;
  return request.substr(at, request.find("\r\n", at) - at);
}

// A server frame (never masked).
Bytes ws_server_frame(std::uint8_t first_byte, const Bytes& payload) {
  Bytes out{first_byte};
  if (payload.size() < 126) {
    out.push_back(static_cast<std::uint8_t>(payload.size()));
  } else {
    out.push_back(126);
    out.push_back(static_cast<std::uint8_t>(payload.size() >> 8));
    out.push_back(static_cast<std::uint8_t>(payload.size()));
  }
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

struct WsReceived {
  std::vector<Bytes> messages, replies;
  std::string feed(WebSocketClient& ws, const Bytes& bytes) {
    return ws.feed(
        bytes, [&](std::span<const std::uint8_t> m) { messages.emplace_back(m.begin(), m.end()); },
        [&](Bytes r) { replies.push_back(std::move(r)); });
  }
};

std::string ws_answer_to(const std::string& request) {
  return "HTTP/1.1 101 Switching Protocols\r\nupgrade: WebSocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept:  " +
         WebSocketClient::accept_for(ws_key_of(request)) + " \r\n\r\n";
}

}  // namespace

TEST_CASE("WebSocketClient: the upgrade's key is checked in the answer, byte by byte or at once") {
  CHECK(WebSocketClient::accept_for("dGhlIHNhbXBsZSBub25jZQ==") == "s3pPLMBiTxaQ9kYGzzhZRbK+xOo=");  // RFC 6455 1.3
  WebSocketClient ws(1, 1 << 16);
  const std::string request = ws.upgrade_request("ocean.example", "7702");
  CHECK(request.rfind("GET / HTTP/1.1\r\nHost: ocean.example:7702\r\n", 0) == 0);
  CHECK(request.find("Sec-WebSocket-Version: 13\r\n") != std::string::npos);
  const std::string key = ws_key_of(request);
  CHECK(key.size() == 24);  // 16 random bytes in base64
  WebSocketClient other(2, 1 << 16);
  CHECK(ws_key_of(other.upgrade_request("h", "1")) != key);  // each client its own key

  // The server's answer, computed here as RFC 6455 4.2.2 says (its example: this key and accept).
  WebSocketClient example(1, 1 << 16);
  WsReceived got;
  const std::string wrong = "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                            "Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n\r\n";
  example.upgrade_request("h", "1");
  // A random key is not the RFC's "dGhlIHNhbXBsZSBub25jZQ==", so its accept value is refused.
  CHECK(got.feed(example, ws_bytes_of(wrong)) == "WebSocket upgrade: Sec-WebSocket-Accept does not answer the key");
  CHECK(!example.open());

  // The right answer, a byte at a time, with a frame right behind it in the last piece.
  WebSocketClient answered(5, 1 << 16);
  const Bytes answer = ws_bytes_of(ws_answer_to(answered.upgrade_request("h", "1")));
  for (std::size_t i = 0; i + 1 < answer.size(); ++i) CHECK(got.feed(answered, {answer[i]}).empty());
  CHECK(!answered.open());
  Bytes last{answer.back()};
  const Bytes frame = ws_server_frame(0x82, {1, 2, 3});
  last.insert(last.end(), frame.begin(), frame.end());
  CHECK(got.feed(answered, last).empty());
  CHECK(answered.open());
  CHECK(got.messages.empty());  // the caller starts its session first: the frame waits for the next call
  CHECK(got.feed(answered, {}).empty());
  REQUIRE(got.messages.size() == 1);
  CHECK(got.messages[0] == Bytes{1, 2, 3});

  WebSocketClient refused(3, 1 << 16);
  refused.upgrade_request("h", "1");
  CHECK(got.feed(refused, ws_bytes_of("HTTP/1.1 403 Forbidden\r\nContent-Length: 0\r\n\r\n")) ==
        "WebSocket upgrade refused: HTTP/1.1 403 Forbidden");
  WebSocketClient silent(4, 1 << 16);
  silent.upgrade_request("h", "1");
  CHECK(got.feed(silent, Bytes(9000, 'x')).find("no answer within") != std::string::npos);
}

TEST_CASE("WebSocketClient: masked binary frames of every length class") {
  WebSocketClient ws(7, 1 << 17);
  for (const std::size_t n : {std::size_t{0}, std::size_t{125}, std::size_t{126}, std::size_t{65535}, std::size_t{65536}}) {
    Bytes message(n);
    for (std::size_t i = 0; i < n; ++i) message[i] = static_cast<std::uint8_t>(i * 7);
    const Bytes frame = ws.frame(message);
    REQUIRE(frame.size() >= 6);
    CHECK(frame[0] == 0x82);          // final, binary
    CHECK((frame[1] & 0x80) != 0);    // masked, as a client must
    const std::size_t head = n < 126 ? 2 : n <= 0xFFFF ? 4 : 10;
    REQUIRE(frame.size() == head + 4 + n);
    std::uint64_t length = frame[1] & 0x7f;
    if (head > 2) {
      length = 0;
      for (std::size_t i = 2; i < head; ++i) length = length << 8 | frame[i];
    }
    CHECK(length == n);
    bool same = true;
    for (std::size_t i = 0; i < n; ++i) same &= (frame[head + 4 + i] ^ frame[head + i % 4]) == message[i];
    CHECK(same);
  }
}

TEST_CASE("WebSocketClient: whole messages from fragments and split frames; Pings answered; every end named") {
  WebSocketClient ws(9, 1000);
  WsReceived got;
  REQUIRE(got.feed(ws, ws_bytes_of(ws_answer_to(ws.upgrade_request("h", "1")))).empty());
  // A message in three fragments with a Ping between them, fed in 3-byte pieces.
  Bytes stream = ws_server_frame(0x02, {1, 2});
  for (const Bytes& part : {ws_server_frame(0x89, {'p'}), ws_server_frame(0x00, {3}), ws_server_frame(0x80, {4, 5}),
                            ws_server_frame(0x82, Bytes(300, 9))})
    stream.insert(stream.end(), part.begin(), part.end());
  for (std::size_t i = 0; i < stream.size(); i += 3)
    REQUIRE(got.feed(ws, Bytes(stream.begin() + static_cast<std::ptrdiff_t>(i),
                               stream.begin() + static_cast<std::ptrdiff_t>(std::min(stream.size(), i + 3)))).empty());
  REQUIRE(got.messages.size() == 2);
  CHECK(got.messages[0] == Bytes{1, 2, 3, 4, 5});
  CHECK(got.messages[1] == Bytes(300, 9));
  REQUIRE(got.replies.size() == 1);  // the Pong, masked, with the Ping's payload
  CHECK(got.replies[0][0] == 0x8A);
  CHECK((got.replies[0][1] & 0x7f) == 1);
  CHECK((got.replies[0][6] ^ got.replies[0][2]) == 'p');

  const auto ends = [](const Bytes& bytes) {
    WebSocketClient c(11, 1000);
    WsReceived r;
    if (!r.feed(c, ws_bytes_of(ws_answer_to(c.upgrade_request("h", "1")))).empty()) return std::string("not opened");
    return r.feed(c, bytes);
  };
  CHECK(ends(ws_server_frame(0x88, {0x03, 0xE8})) == "WebSocket closed by the server (1000)");
  CHECK(ends(ws_server_frame(0x81, ws_bytes_of("text"))) == "WebSocket: unexpected frame (opcode 1)");
  CHECK(ends(ws_server_frame(0x80, {1})) == "WebSocket: unexpected frame (opcode 0)");  // a continuation of nothing
  CHECK(ends(ws_server_frame(0xC2, {1})) == "WebSocket: a frame with reserved bits set");
  CHECK(ends(Bytes{0x82, 0x81, 0, 0, 0, 0, 1}) == "WebSocket: the server masked a frame");
  CHECK(ends(ws_server_frame(0x82, Bytes(1100, 0))).find("over the message limit") != std::string::npos);
  Bytes parts = ws_server_frame(0x02, Bytes(600, 0));
  const Bytes more = ws_server_frame(0x80, Bytes(600, 0));
  parts.insert(parts.end(), more.begin(), more.end());
  CHECK(ends(parts) == "WebSocket: a message over the limit");  // each fragment fits, the whole does not
}
