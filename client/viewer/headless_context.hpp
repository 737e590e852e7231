// A GLES 2 context with no window and no X server: EGL on Mesa's surfaceless platform (falling
// back to the default display), made current without a surface or with a 1x1 pbuffer. Drawing
// goes to an OffscreenTarget.
#pragma once

#include <string>

namespace ocean::viewer {

class HeadlessContext {
 public:
  HeadlessContext() = default;
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;
  ~HeadlessContext() { destroy(); }

  // On failure says which EGL step failed and with which EGL error.
  bool create(std::string& error);
  void destroy();
  const std::string& description() const { return description_; }  // EGL vendor, GL renderer

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  void* surface_ = nullptr;  // EGLSurface (pbuffer) or null when surfaceless
  std::string description_;
};

}  // namespace ocean::viewer
