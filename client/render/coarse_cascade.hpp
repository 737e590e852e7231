// CoarseCascade: the GL side of a coarse cascade (common/cascade.hpp), a larger lattice of the same
// sea that the ocean shader samples at each vertex and adds to the streamed tile, so that the sea
// repeats only every coarse patch instead of every tile. Two float textures per frame: (height,
// dh/dx, dh/dz, 0) and (displacement x, z, J - 1, 0). GLES 2 makes both vertex texture fetch and
// float textures optional: supported() says whether this GL has them.
#pragma once

#include <string>
#include <vector>

#include <GLES2/gl2.h>

namespace ocean::render {

struct FrameStreams;

class CoarseCascade {
 public:
  CoarseCascade() = default;
  CoarseCascade(const CoarseCascade&) = delete;
  CoarseCascade& operator=(const CoarseCascade&) = delete;
  ~CoarseCascade() { destroy(); }

  // Needs a current context: at least two vertex texture units and GL_OES_texture_float.
  static bool supported();

  // n x n samples (a power of two, 2..2048) over patch_x_m x patch_z_m; false with `error` set.
  bool create(int n, float patch_x_m, float patch_z_m, std::string& error);
  void destroy();
  bool active() const { return shape_ != 0; }

  // Height is required; missing slopes come from central differences, missing displacement is 0
  // and a missing Jacobian is 1.
  bool upload(const FrameStreams& frame, std::string& error);

  // Binds the textures to units `first` and `first + 1`.
  void bind(GLenum first_unit) const;

  int n() const { return n_; }
  float patch_x() const { return patch_x_; }
  float patch_z() const { return patch_z_; }
  float max_height() const { return max_height_; }
  float max_displacement() const { return max_disp_; }

 private:
  GLuint shape_ = 0, chop_ = 0;
  int n_ = 0;
  float patch_x_ = 0.0f, patch_z_ = 0.0f;
  float max_height_ = 0.0f, max_disp_ = 0.0f;
  std::vector<float> texels_, slope_x_, slope_z_;
};

}  // namespace ocean::render
