// View-frustum planes extracted from a clip matrix, and the box test used to cull ocean tiles.
// Pure math: the planes live in whatever space the matrix maps from (the renderer uses
// camera-relative space).
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace ocean::render {

struct Aabb {
  glm::vec3 min;
  glm::vec3 max;
};

enum class Containment { outside, intersecting, inside };

// A point p is on the inner side when dot(normal, p) + offset >= 0; normal is unit length.
struct Plane {
  glm::vec3 normal;
  float offset;
};

class Frustum {
 public:
  // Gribb/Hartmann extraction; clip_from_space must be a GL-style projection (z in [-w, w]).
  static Frustum from_clip_matrix(const glm::mat4& clip_from_space);

  Containment classify(const Aabb& box) const;
  bool may_see(const Aabb& box) const { return classify(box) != Containment::outside; }
  const std::array<Plane, 6>& planes() const { return planes_; }

 private:
  std::array<Plane, 6> planes_{};  // left, right, bottom, top, near, far
};

}  // namespace ocean::render
