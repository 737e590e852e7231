// hull_mesh: a hull sized from its length, beam and draft - inside its box, keel at the draft,
// every face's normal unit and pointing away from the hull's middle, valid triangles.
#include "client/render/hull_mesh.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

using ocean::render::hull_mesh;
using ocean::render::HullMesh;

TEST_CASE("a hull mesh fits its length, beam and draft and faces outwards") {
  for (const auto& [length, beam, draft] : {std::tuple{30.0f, 7.0f, 2.0f}, std::tuple{12.0f, 4.0f, 0.8f}, std::tuple{400.0f, 60.0f, 25.0f}}) {
    INFO("hull " << length << " x " << beam << " x " << draft);
    const HullMesh mesh = hull_mesh(length, beam, draft);
    REQUIRE(mesh.vertices.size() < 65536);
    REQUIRE(mesh.indices.size() % 3 == 0);
    REQUIRE(!mesh.indices.empty());
    float min_y = 0.0f, max_x = -1e9f, min_x = 1e9f, max_z = 0.0f;
    for (const auto& v : mesh.vertices) {
      min_y = std::min(min_y, v.position.y);
      max_x = std::max(max_x, v.position.x);
      min_x = std::min(min_x, v.position.x);
      max_z = std::max(max_z, std::abs(v.position.z));
      CHECK(glm::length(v.normal) == Approx(1.0f).margin(1e-4));
      CHECK(glm::length(v.position) <= mesh.radius_m + 1e-3f);
    }
    CHECK(min_y == Approx(-draft));                // the keel amidships
    CHECK(max_x == Approx(length / 2));           // the stem
    CHECK(min_x == Approx(-length / 2));          // the transom
    CHECK(max_z == Approx(beam / 2));
    CHECK(mesh.freeboard_m > 0.0f);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
      const auto& a = mesh.vertices[mesh.indices[i]];
      const auto& b = mesh.vertices[mesh.indices[i + 1]];
      const auto& c = mesh.vertices[mesh.indices[i + 2]];
      // The triangle's winding agrees with its stored normal, and the normal points away from a
      // point on the hull's centre line at its height (the hull is convex across its beam).
      const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
      if (glm::length(n) < 1e-6f) continue;
      CHECK(glm::dot(n, a.normal) > 0.0f);
      const glm::vec3 centre = (a.position + b.position + c.position) / 3.0f;
      if (std::abs(centre.z) > 0.05f * beam && std::abs(a.normal.z) > 0.3f)  // a side, not the deck or house ends
        CHECK(centre.z * a.normal.z > 0.0f);
    }
  }
}
