#include "client/viewer/app_window.hpp"

#include <GLFW/glfw3.h>

namespace ocean::viewer {

namespace {

std::string glfw_error_text() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  return code == GLFW_NO_ERROR ? std::string("no GLFW error reported") : std::string(description ? description : "?");
}

}  // namespace

bool AppWindow::open(const WindowDesc& desc, std::string& error) {
  close();
  if (!glfwInit()) {
    error = "glfwInit failed: " + glfw_error_text() + " (no display? run under xvfb-run -a, or use --headless)";
    return false;
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  const int width = desc.width > 0 ? desc.width : 1280;
  const int height = desc.height > 0 ? desc.height : 720;
  window_ = glfwCreateWindow(width, height, desc.title ? desc.title : "ocean", nullptr, nullptr);
  if (!window_) {
    error = "glfwCreateWindow (OpenGL ES 2 through EGL) failed: " + glfw_error_text();
    glfwTerminate();
    return false;
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(desc.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &AppWindow::on_key);
  glfwSetCursorPosCallback(window_, &AppWindow::on_cursor);
  glfwSetMouseButtonCallback(window_, &AppWindow::on_button);
  return true;
}

void AppWindow::close() {
  if (!window_) return;
  glfwDestroyWindow(window_);
  window_ = nullptr;
  glfwTerminate();
}

bool AppWindow::should_close() const { return !window_ || glfwWindowShouldClose(window_); }

render::FlyInput AppWindow::poll() {
  glfwPollEvents();
  render::FlyInput in;
  if (!window_) return in;
  const auto down = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
  in.forward = down(GLFW_KEY_W) || down(GLFW_KEY_UP);
  in.back = down(GLFW_KEY_S) || down(GLFW_KEY_DOWN);
  in.left = down(GLFW_KEY_A) || down(GLFW_KEY_LEFT);
  in.right = down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT);
  in.up = down(GLFW_KEY_E) || down(GLFW_KEY_SPACE);
  in.down = down(GLFW_KEY_C);
  in.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
  in.look_dx_px = drag_dx_;
  in.look_dy_px = drag_dy_;
  drag_dx_ = drag_dy_ = 0.0;
  return in;
}

void AppWindow::swap() {
  if (window_) glfwSwapBuffers(window_);
}

void AppWindow::framebuffer_size(int& width, int& height) const {
  width = height = 0;
  if (window_) glfwGetFramebufferSize(window_, &width, &height);
}

void AppWindow::toggle_fullscreen() {
  if (glfwGetWindowMonitor(window_)) {
    glfwSetWindowMonitor(window_, nullptr, windowed_x_, windowed_y_, windowed_w_, windowed_h_, GLFW_DONT_CARE);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  if (!mode) return;
  glfwGetWindowPos(window_, &windowed_x_, &windowed_y_);
  glfwGetWindowSize(window_, &windowed_w_, &windowed_h_);
  glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

void AppWindow::on_key(GLFWwindow* w, int key, int, int action, int) {
  auto* self = static_cast<AppWindow*>(glfwGetWindowUserPointer(w));
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_Q || key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
  if (key == GLFW_KEY_F) self->toggle_fullscreen();
  if (key == GLFW_KEY_H) self->hud_visible_ = !self->hud_visible_;
  if (key == GLFW_KEY_V) ++self->follow_presses_;
}

void AppWindow::on_cursor(GLFWwindow* w, double x, double y) {
  auto* self = static_cast<AppWindow*>(glfwGetWindowUserPointer(w));
  if (self->dragging_) {
    self->drag_dx_ += x - self->last_x_;
    self->drag_dy_ += y - self->last_y_;
  }
  self->last_x_ = x;
  self->last_y_ = y;
}

void AppWindow::on_button(GLFWwindow* w, int button, int action, int) {
  auto* self = static_cast<AppWindow*>(glfwGetWindowUserPointer(w));
  if (button == GLFW_MOUSE_BUTTON_LEFT || button == GLFW_MOUSE_BUTTON_RIGHT) {
    self->dragging_ = action == GLFW_PRESS;
    glfwGetCursorPos(w, &self->last_x_, &self->last_y_);
  }
}

}  // namespace ocean::viewer
