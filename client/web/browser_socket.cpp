// BrowserSocket over Emscripten's WebSocket API (-lwebsocket.js).
#include "browser_socket.hpp"

#include <emscripten/websocket.h>

namespace ocean::web {

struct BrowserSocket::Callbacks {
  static EM_BOOL open(int, const EmscriptenWebSocketOpenEvent*, void* self) {
    auto* s = static_cast<BrowserSocket*>(self);
    s->opened_ = true;
    if (s->events_.on_open) s->events_.on_open();
    return EM_TRUE;
  }
  static EM_BOOL message(int, const EmscriptenWebSocketMessageEvent* e, void* self) {
    auto* s = static_cast<BrowserSocket*>(self);
    if (e->isText)
      s->end("the server sent a text message; the protocol is binary");
    else if (s->events_.on_message)
      s->events_.on_message(std::span<const std::uint8_t>(e->data, e->numBytes));
    return EM_TRUE;
  }
  static EM_BOOL error(int, const EmscriptenWebSocketErrorEvent*, void* self) {
    static_cast<BrowserSocket*>(self)->end("WebSocket error (server unreachable, or its Origin list refused this page)");
    return EM_TRUE;
  }
  static EM_BOOL close(int, const EmscriptenWebSocketCloseEvent* e, void* self) {
    std::string why = "WebSocket closed, code " + std::to_string(e->code);
    if (e->reason[0]) why += std::string(": ") + e->reason;
    static_cast<BrowserSocket*>(self)->end(why);
    return EM_TRUE;
  }
};

bool BrowserSocket::open(const std::string& url, BrowserSocketEvents events, std::string& error) {
  close();
  EmscriptenWebSocketCreateAttributes attributes;
  emscripten_websocket_init_create_attributes(&attributes);
  attributes.url = url.c_str();
  attributes.protocols = nullptr;
  const EMSCRIPTEN_WEBSOCKET_T socket = emscripten_websocket_new(&attributes);
  if (socket <= 0) {
    error = "the browser refused the WebSocket URL " + url;
    return false;
  }
  socket_ = socket;
  events_ = std::move(events);
  emscripten_websocket_set_onopen_callback(socket, this, &Callbacks::open);
  emscripten_websocket_set_onmessage_callback(socket, this, &Callbacks::message);
  emscripten_websocket_set_onerror_callback(socket, this, &Callbacks::error);
  emscripten_websocket_set_onclose_callback(socket, this, &Callbacks::close);
  return true;
}

void BrowserSocket::send(std::span<const std::uint8_t> bytes) {
  if (!is_open() || bytes.empty()) return;
  emscripten_websocket_send_binary(socket_, const_cast<std::uint8_t*>(bytes.data()), static_cast<std::uint32_t>(bytes.size()));
}

std::uint64_t BrowserSocket::buffered() const {
  unsigned long long amount = 0;
  if (socket_ > 0) emscripten_websocket_get_buffered_amount(socket_, &amount);
  return amount;
}

void BrowserSocket::close() {
  if (socket_ <= 0) return;
  const int socket = socket_;
  socket_ = 0;
  opened_ = false;
  emscripten_websocket_close(socket, 1000, "viewer closed");
  emscripten_websocket_delete(socket);  // no callback of it runs after this
}

void BrowserSocket::end(const std::string& why) {
  if (socket_ <= 0) return;
  const BrowserSocketEvents events = events_;
  close();
  if (events.on_closed) events.on_closed(why);
}


}  // namespace ocean::web
