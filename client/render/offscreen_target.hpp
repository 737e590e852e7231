// An off-screen framebuffer (colour + depth renderbuffers) for headless rendering, where the
// context has no window surface to draw into.
#pragma once

#include <string>

#include <GLES2/gl2.h>

namespace ocean::render {

class OffscreenTarget {
 public:
  OffscreenTarget() = default;
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;
  ~OffscreenTarget() { destroy(); }

  // Needs a current context. Uses RGBA8 / 24-bit depth where the OES extensions allow.
  bool create(int width, int height, std::string& error);
  void bind() const;
  void destroy();
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GLuint framebuffer_ = 0, colour_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace ocean::render
