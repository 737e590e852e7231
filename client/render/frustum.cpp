#include "client/render/frustum.hpp"

namespace ocean::render {

namespace {

glm::vec4 row(const glm::mat4& m, int i) { return {m[0][i], m[1][i], m[2][i], m[3][i]}; }

Plane normalized(const glm::vec4& p) {
  const float len = glm::length(glm::vec3(p));
  return {glm::vec3(p) / len, p.w / len};
}

}  // namespace

Frustum Frustum::from_clip_matrix(const glm::mat4& m) {
  const glm::vec4 r0 = row(m, 0), r1 = row(m, 1), r2 = row(m, 2), r3 = row(m, 3);
  Frustum f;
  f.planes_ = {normalized(r3 + r0), normalized(r3 - r0), normalized(r3 + r1),
               normalized(r3 - r1), normalized(r3 + r2), normalized(r3 - r2)};
  return f;
}

Containment Frustum::classify(const Aabb& box) const {
  Containment result = Containment::inside;
  for (const Plane& p : planes_) {
    // The corner furthest along the normal decides "outside"; the nearest one decides "inside".
    const glm::vec3 far_corner{p.normal.x >= 0 ? box.max.x : box.min.x,
                               p.normal.y >= 0 ? box.max.y : box.min.y,
                               p.normal.z >= 0 ? box.max.z : box.min.z};
    const glm::vec3 near_corner{p.normal.x >= 0 ? box.min.x : box.max.x,
                                p.normal.y >= 0 ? box.min.y : box.max.y,
                                p.normal.z >= 0 ? box.min.z : box.max.z};
    if (glm::dot(p.normal, far_corner) + p.offset < 0.0f) return Containment::outside;
    if (glm::dot(p.normal, near_corner) + p.offset < 0.0f) result = Containment::intersecting;
  }
  return result;
}

}  // namespace ocean::render
