#include "client/render/offscreen_target.hpp"

#include "client/render/gl_program.hpp"

#include <cstdio>

#include <GLES2/gl2ext.h>

namespace ocean::render {

bool OffscreenTarget::create(int width, int height, std::string& error) {
  destroy();
  if (width <= 0 || height <= 0) {
    error = "off-screen target size must be positive, got " + std::to_string(width) + "x" + std::to_string(height);
    return false;
  }
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width > max_size || height > max_size) {
    error = "off-screen target " + std::to_string(width) + "x" + std::to_string(height) +
            " exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_size);
    return false;
  }
  const GLenum colour_format = has_extension("GL_OES_rgb8_rgba8") ? GL_RGBA8_OES : GL_RGB565;
  const GLenum depth_format = has_extension("GL_OES_depth24") ? GL_DEPTH_COMPONENT24_OES : GL_DEPTH_COMPONENT16;
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &colour_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, colour_format, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, depth_format, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(status));
    error = std::string("off-screen framebuffer incomplete, glCheckFramebufferStatus = ") + hex;
    destroy();
    return false;
  }
  width_ = width;
  height_ = height;
  return true;
}

void OffscreenTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_); }

void OffscreenTarget::destroy() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_) glDeleteRenderbuffers(1, &colour_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  framebuffer_ = colour_ = depth_ = 0;
  width_ = height_ = 0;
}

}  // namespace ocean::render
