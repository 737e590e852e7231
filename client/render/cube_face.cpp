#include "client/render/cube_face.hpp"

namespace ocean::render {

glm::vec3 cube_face_direction(int face, float s, float t) {
  // Inverse of the major-axis selection table in the GLES 2 spec (section 3.7.5).
  const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
  glm::vec3 d{0.0f};
  switch (face) {
    case 0: d = {1.0f, -tc, -sc}; break;
    case 1: d = {-1.0f, -tc, sc}; break;
    case 2: d = {sc, 1.0f, tc}; break;
    case 3: d = {sc, -1.0f, -tc}; break;
    case 4: d = {sc, -tc, 1.0f}; break;
    default: d = {-sc, -tc, -1.0f}; break;
  }
  return glm::normalize(d);
}

CubeTexel cube_face_texel(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0.0f ? 0 : 1;
    sc = d.x >= 0.0f ? -d.z : d.z;
    tc = -d.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = d.y >= 0.0f ? 2 : 3;
    sc = d.x;
    tc = d.y >= 0.0f ? d.z : -d.z;
    ma = a.y;
  } else {
    face = d.z >= 0.0f ? 4 : 5;
    sc = d.z >= 0.0f ? d.x : -d.x;
    tc = -d.y;
    ma = a.z;
  }
  return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

}  // namespace ocean::render
