// The OpenGL cube-map convention in one place: which world direction each texel of each face
// looks along. The sky generator writes faces with it and the renderer reads them back with it.
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace ocean::render {

// Faces in GL_TEXTURE_CUBE_MAP_POSITIVE_X + i order, named as the files on disk.
inline constexpr std::array<std::string_view, 6> kCubeFaceNames{"px", "nx", "py", "ny", "pz", "nz"};

// Unit direction through texel coordinate (s, t) in [0, 1]^2 of a face; t = 0 is the first
// row of the image as uploaded (the top row of the PNG).
glm::vec3 cube_face_direction(int face, float s, float t);

struct CubeTexel {
  int face;
  float s, t;  // in [0, 1]
};

// The face and texel coordinate a (non-zero) direction samples; inverse of cube_face_direction.
CubeTexel cube_face_texel(const glm::vec3& direction);

}  // namespace ocean::render
