// The desktop window: GLFW with an OpenGL ES 2 context created through EGL, and the viewer's
// keys gathered into plain state (W/S/A/D move, mouse drag looks, F fullscreen, H HUD, Q/Esc quit).
#pragma once

#include <string>
#include <utility>

#include "client/render/camera_controls.hpp"

struct GLFWwindow;

namespace ocean::viewer {

struct WindowDesc {
  int width = 0;              // 1280
  int height = 0;             // 720
  const char* title = nullptr;  // "ocean"
  bool vsync = true;
};

class AppWindow {
 public:
  AppWindow() = default;
  AppWindow(const AppWindow&) = delete;
  AppWindow& operator=(const AppWindow&) = delete;
  ~AppWindow() { close(); }

  bool open(const WindowDesc& desc, std::string& error);
  void close();

  bool should_close() const;
  // Polls events and returns the fly-camera input gathered since the previous call.
  render::FlyInput poll();
  void swap();
  void framebuffer_size(int& width, int& height) const;
  bool hud_visible() const { return hud_visible_; }
  // Presses of V since the last call: each moves the follow camera to the next vessel.
  int take_follow_presses() { return std::exchange(follow_presses_, 0); }

 private:
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_button(GLFWwindow* w, int button, int action, int mods);
  void toggle_fullscreen();

  GLFWwindow* window_ = nullptr;
  bool hud_visible_ = true;
  int follow_presses_ = 0;
  bool dragging_ = false;
  double last_x_ = 0.0, last_y_ = 0.0, drag_dx_ = 0.0, drag_dy_ = 0.0;
  int windowed_x_ = 0, windowed_y_ = 0, windowed_w_ = 0, windowed_h_ = 0;
};

}  // namespace ocean::viewer
