// BrowserSocket: the web viewer's one transport - a browser WebSocket (emscripten/websocket.h)
// whose binary messages are whole protocol messages, size prefix included (PROTOCOL.md 4.1), so
// each one goes to ClientSession::on_tcp_message as it is. Callbacks run on the browser's event
// loop, between animation frames.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace ocean::web {

struct BrowserSocketEvents {
  std::function<void()> on_open;
  std::function<void(std::span<const std::uint8_t>)> on_message;
  std::function<void(const std::string& why)> on_closed;  // once, for any end (error, close, refusal)
};

class BrowserSocket {
 public:
  BrowserSocket() = default;
  ~BrowserSocket() { close(); }
  BrowserSocket(const BrowserSocket&) = delete;
  BrowserSocket& operator=(const BrowserSocket&) = delete;

  // url: ws://host:port/ (or wss://). False with a reason when the browser refuses it at once.
  bool open(const std::string& url, BrowserSocketEvents events, std::string& error);
  void send(std::span<const std::uint8_t> bytes);
  // Bytes the browser still holds to send (WebSocket.bufferedAmount).
  std::uint64_t buffered() const;
  void close();
  bool is_open() const { return socket_ > 0 && opened_; }

 private:
  struct Callbacks;  // the browser's callbacks, typed as emscripten/websocket.h declares them
  friend struct Callbacks;
  void end(const std::string& why);

  int socket_ = 0;
  bool opened_ = false;
  BrowserSocketEvents events_;
};

}  // namespace ocean::web
