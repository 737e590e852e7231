// ocean-web: the browser viewer's entry point. Creates a WebGL 1 context on the page's #ocean
// canvas, wires mouse, keyboard and touch to the camera, runs WebViewer::frame on every
// animation frame, and exports the calls the page makes (index.html's viewer.js).
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/json_writer.hpp"
#include "web_viewer.hpp"

namespace {

constexpr const char* kCanvas = "#ocean";
ocean::web::WebViewer* viewer = nullptr;
bool dragging = false;
std::string text_out;  // what the last exported call that returns text returned
std::string startup_error;  // why there is no viewer (no WebGL, the renderer refused)

EM_BOOL on_mouse(int type, const EmscriptenMouseEvent* e, void*) {
  if (type == EMSCRIPTEN_EVENT_MOUSEDOWN) {
    dragging = true;
    return EM_FALSE;  // the browser's default still gives the canvas the keyboard focus
  }
  if (type == EMSCRIPTEN_EVENT_MOUSEUP) dragging = false;
  if (type == EMSCRIPTEN_EVENT_MOUSEMOVE && dragging && (e->buttons & 1)) viewer->look(e->movementX, e->movementY);
  return EM_TRUE;
}

// Keys held when the canvas loses focus never see their keyup: let go of them all.
EM_BOOL on_blur(int, const EmscriptenFocusEvent*, void*) {
  viewer->keys() = {};
  dragging = false;
  return EM_TRUE;
}

EM_BOOL on_key(int type, const EmscriptenKeyboardEvent* e, void*) {
  if (std::strcmp(e->code, "KeyV") == 0 && type == EMSCRIPTEN_EVENT_KEYDOWN) {
    viewer->cycle_follow();
    return EM_TRUE;
  }
  if (std::strcmp(e->code, "KeyH") == 0 && type == EMSCRIPTEN_EVENT_KEYDOWN) {
    static bool hud = true;
    viewer->set_hud(hud = !hud);
    return EM_TRUE;
  }
  ocean::render::FlyInput& k = viewer->keys();
  const bool down = type == EMSCRIPTEN_EVENT_KEYDOWN;
  const std::string code = e->code;
  if (code == "KeyW" || code == "ArrowUp") k.forward = down;
  else if (code == "KeyS" || code == "ArrowDown") k.back = down;
  else if (code == "KeyA" || code == "ArrowLeft") k.left = down;
  else if (code == "KeyD" || code == "ArrowRight") k.right = down;
  else if (code == "KeyE" || code == "Space") k.up = down;
  else if (code == "KeyC") k.down = down;
  else if (code == "ShiftLeft" || code == "ShiftRight") k.fast = down;
  else return EM_FALSE;  // the page keeps every other key
  return EM_TRUE;
}

EM_BOOL on_touch(int type, const EmscriptenTouchEvent* e, void*) {
  const bool lifting = type == EMSCRIPTEN_EVENT_TOUCHEND || type == EMSCRIPTEN_EVENT_TOUCHCANCEL;
  std::vector<ocean::render::TouchPoint> down;
  for (int i = 0; i < e->numTouches; ++i) {
    const EmscriptenTouchPoint& t = e->touches[i];
    if (lifting && t.isChanged) continue;  // the finger that lifted
    down.push_back({t.identifier, static_cast<double>(t.targetX), static_cast<double>(t.targetY)});
  }
  viewer->touches(down);
  return EM_TRUE;  // no page scroll or zoom over the sea
}

void frame() {
  int width = 0, height = 0;
  emscripten_get_canvas_element_size(kCanvas, &width, &height);
  viewer->frame(emscripten_get_now() / 1000.0, width, height);
}

}  // namespace

extern "C" {

// Each call is a no-op (or reports the failure) when main() found no WebGL and made no viewer.
EMSCRIPTEN_KEEPALIVE void ocean_web_connect(const char* url, int profile_id) {
  if (viewer) viewer->connect(url, static_cast<std::uint8_t>(profile_id));
}
EMSCRIPTEN_KEEPALIVE void ocean_web_disconnect() {
  if (viewer) viewer->disconnect();
}
EMSCRIPTEN_KEEPALIVE void ocean_web_camera(double x, double y, double z, double pitch_deg, double yaw_deg) {
  if (viewer) viewer->place_camera(x, y, z, pitch_deg, yaw_deg);
}
EMSCRIPTEN_KEEPALIVE void ocean_web_follow(double id) {
  if (viewer) viewer->set_follow(static_cast<std::int64_t>(id));
}
EMSCRIPTEN_KEEPALIVE void ocean_web_record(int on) {
  if (viewer) viewer->set_recording(on != 0);
}
EMSCRIPTEN_KEEPALIVE const char* ocean_web_report() {
  text_out = viewer ? viewer->report()
                    : ocean::common::JsonWriter(ocean::common::JsonWriter::Style::compact)
                          .text("state", "failed").text("close_reason", startup_error).str();
  return text_out.c_str();
}
EMSCRIPTEN_KEEPALIVE const char* ocean_web_recorded_messages() {
  text_out = viewer ? viewer->recorded_messages() : "";
  return text_out.c_str();
}

}  // extern "C"

int main() {
  EmscriptenWebGLContextAttributes attributes;
  emscripten_webgl_init_context_attributes(&attributes);
  attributes.majorVersion = 1;  // WebGL 1 is OpenGL ES 2: the shaders as they are
  attributes.minorVersion = 0;
  attributes.depth = EM_TRUE;
  attributes.alpha = EM_FALSE;  // opaque: the page composites the canvas without blending it
  attributes.antialias = EM_FALSE;
  attributes.preserveDrawingBuffer = EM_FALSE;  // a copy per frame otherwise; screenshots read the composited page
  const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context(kCanvas, &attributes);
  if (context <= 0 || emscripten_webgl_make_context_current(context) != EMSCRIPTEN_RESULT_SUCCESS) {
    startup_error = "this browser gives no WebGL 1 context";
    std::fprintf(stderr, "ocean-web: %s\n", startup_error.c_str());
    return 1;
  }
  static ocean::web::WebViewer instance;
  std::string error;
  if (!instance.init(error)) {
    startup_error = "renderer: " + error;
    std::fprintf(stderr, "ocean-web: %s\n", startup_error.c_str());
    return 1;
  }
  viewer = &instance;
  emscripten_set_mousedown_callback(kCanvas, nullptr, EM_TRUE, on_mouse);
  emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_TRUE, on_mouse);
  emscripten_set_mousemove_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_TRUE, on_mouse);
  // On the canvas (it has a tabindex), so typing in the connect box moves nothing.
  emscripten_set_keydown_callback(kCanvas, nullptr, EM_TRUE, on_key);
  emscripten_set_keyup_callback(kCanvas, nullptr, EM_TRUE, on_key);
  emscripten_set_blur_callback(kCanvas, nullptr, EM_TRUE, on_blur);
  emscripten_set_touchstart_callback(kCanvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchmove_callback(kCanvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchend_callback(kCanvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchcancel_callback(kCanvas, nullptr, EM_TRUE, on_touch);
  std::fprintf(stderr, "ocean-web: ready\n");
  emscripten_set_main_loop(frame, 0, 0);
  return 0;
}
