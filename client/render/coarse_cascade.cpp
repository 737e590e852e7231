#include "client/render/coarse_cascade.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "client/render/periodic_field.hpp"
#include "client/render/renderer.hpp"

namespace ocean::render {

namespace {

GLuint nearest_repeat_texture() {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  return t;
}

}  // namespace

bool CoarseCascade::supported() {
  GLint units = 0;
  glGetIntegerv(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, &units);
  const char* all = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  return units >= 2 && all && std::strstr(all, "GL_OES_texture_float") != nullptr;
}

bool CoarseCascade::create(int n, float patch_x_m, float patch_z_m, std::string& error) {
  destroy();
  if (n < 2 || n > 2048 || (n & (n - 1)) != 0) {
    error = "coarse cascade: n = " + std::to_string(n) + " samples per side, allowed powers of two 2..2048";
    return false;
  }
  if (!(patch_x_m > 0.0f) || !(patch_z_m > 0.0f)) {
    error = "coarse cascade: patch size must be > 0 metres";
    return false;
  }
  if (!supported()) {
    error = "coarse cascade: this GL has no vertex texture fetch (2 units) or no GL_OES_texture_float";
    return false;
  }
  n_ = n;
  patch_x_ = patch_x_m;
  patch_z_ = patch_z_m;
  shape_ = nearest_repeat_texture();
  chop_ = nearest_repeat_texture();
  texels_.assign(static_cast<std::size_t>(n) * n * 4, 0.0f);
  for (GLuint t : {shape_, chop_}) {
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, n, n, 0, GL_RGBA, GL_FLOAT, texels_.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
    error = "coarse cascade: GL error " + std::to_string(e) + " creating its float textures";
    destroy();
    return false;
  }
  return true;
}

void CoarseCascade::destroy() {
  if (shape_) glDeleteTextures(1, &shape_);
  if (chop_) glDeleteTextures(1, &chop_);
  shape_ = chop_ = 0;
  n_ = 0;
  max_height_ = max_disp_ = 0.0f;
}

bool CoarseCascade::upload(const FrameStreams& f, std::string& error) {
  if (!active()) {
    error = "coarse cascade: upload before create";
    return false;
  }
  if (!f.height || (f.disp_x == nullptr) != (f.disp_z == nullptr)) {
    error = "coarse cascade: a frame needs heights, and both displacements or neither";
    return false;
  }
  const std::size_t count = static_cast<std::size_t>(n_) * n_;
  const auto [sx, sz] = slopes_or_differences(n_, patch_x_, patch_z_, f.height, f.slope_x, f.slope_z, slope_x_, slope_z_);
  max_height_ = 0.0f;
  for (std::size_t i = 0; i < count; ++i) {
    texels_[4 * i] = f.height[i];
    texels_[4 * i + 1] = sx[i];
    texels_[4 * i + 2] = sz[i];
    texels_[4 * i + 3] = 0.0f;
    max_height_ = std::max(max_height_, std::abs(f.height[i]));
  }
  glBindTexture(GL_TEXTURE_2D, shape_);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n_, n_, GL_RGBA, GL_FLOAT, texels_.data());
  float max_d2 = 0.0f;
  for (std::size_t i = 0; i < count; ++i) {
    const float dx = f.disp_x ? f.disp_x[i] : 0.0f, dz = f.disp_z ? f.disp_z[i] : 0.0f;
    texels_[4 * i] = dx;
    texels_[4 * i + 1] = dz;
    texels_[4 * i + 2] = f.jacobian ? f.jacobian[i] - 1.0f : 0.0f;
    texels_[4 * i + 3] = 0.0f;
    max_d2 = std::max(max_d2, dx * dx + dz * dz);
  }
  max_disp_ = std::sqrt(max_d2);
  glBindTexture(GL_TEXTURE_2D, chop_);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n_, n_, GL_RGBA, GL_FLOAT, texels_.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
    error = "coarse cascade: GL error " + std::to_string(e) + " uploading a frame";
    return false;
  }
  return true;
}

void CoarseCascade::bind(GLenum first_unit) const {
  glActiveTexture(first_unit);
  glBindTexture(GL_TEXTURE_2D, shape_);
  glActiveTexture(first_unit + 1);
  glBindTexture(GL_TEXTURE_2D, chop_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace ocean::render
