// Camera, frustum, LOD policy and fly controls: the renderer's math, tested without GL.
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>

#include "client/render/camera.hpp"
#include "client/render/camera_controls.hpp"
#include "client/render/frustum.hpp"
#include "client/render/lod.hpp"

using namespace ocean::render;

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) { return glm::length(a - b) < eps; }

Camera level_camera() {
  Camera c;
  c.position = {0.0, 0.0, 0.0};
  c.fov_y_rad = glm::radians(60.0f);
  c.near_m = 0.5f;
  c.far_m = 1000.0f;
  return c;
}

}  // namespace

TEST_CASE("camera looks along -z at zero yaw and turns left with positive yaw") {
  Camera c = level_camera();
  CHECK(near(c.forward(), {0.0f, 0.0f, -1.0f}));
  CHECK(near(c.right(), {1.0f, 0.0f, 0.0f}));
  c.yaw_rad = glm::half_pi<float>();
  CHECK(near(c.forward(), {-1.0f, 0.0f, 0.0f}));
  c.pitch_rad = glm::radians(30.0f);
  CHECK(c.forward().y == Approx(0.5f).margin(1e-6));
  CHECK(glm::dot(c.forward(), c.right()) == Approx(0.0f).margin(1e-6));
}

TEST_CASE("camera projection puts the view centre at NDC origin and points behind at negative w") {
  Camera c = level_camera();
  c.yaw_rad = 0.7f;
  c.pitch_rad = -0.3f;
  const glm::mat4 m = c.clip_from_relative(16.0f / 9.0f);
  const glm::vec4 ahead = m * glm::vec4(c.forward() * 100.0f, 1.0f);
  CHECK(ahead.w > 0.0f);
  CHECK(ahead.x / ahead.w == Approx(0.0f).margin(1e-5));
  CHECK(ahead.y / ahead.w == Approx(0.0f).margin(1e-5));
  CHECK(std::abs(ahead.z / ahead.w) < 1.0f);
  const glm::vec4 behind = m * glm::vec4(-c.forward() * 100.0f, 1.0f);
  CHECK(behind.w < 0.0f);
  // A point on the top edge of the vertical field of view lands on NDC y = 1.
  const glm::vec3 top_dir = glm::normalize(c.forward() * std::cos(c.fov_y_rad / 2) +
                                           glm::cross(c.right(), c.forward()) * std::sin(c.fov_y_rad / 2));
  const glm::vec4 top = m * glm::vec4(top_dir * 50.0f, 1.0f);
  CHECK(top.y / top.w == Approx(1.0f).margin(1e-4));
}

TEST_CASE("frustum classifies boxes inside, outside and straddling") {
  const Camera c = level_camera();  // at the origin looking along -z, 60 deg vertical, 16:9
  const Frustum f = Frustum::from_clip_matrix(c.clip_from_relative(16.0f / 9.0f));
  const auto box = [](glm::vec3 centre, float half) { return Aabb{centre - glm::vec3(half), centre + glm::vec3(half)}; };

  CHECK(f.classify(box({0, 0, -50}, 1)) == Containment::inside);
  CHECK(f.classify(box({0, 0, 50}, 1)) == Containment::outside);        // behind
  CHECK(f.classify(box({-500, 0, -50}, 1)) == Containment::outside);    // far left
  CHECK(f.classify(box({0, 300, -50}, 1)) == Containment::outside);     // above
  CHECK(f.classify(box({0, 0, -2000}, 1)) == Containment::outside);     // past the far plane
  CHECK(f.classify(box({0, 0, -0.1f}, 0.05f)) == Containment::outside); // before the near plane

  // The left plane at z = -50 sits at x = -50 * tan(hfov / 2); a box across it straddles.
  const float half_width = 50.0f * std::tan(c.fov_y_rad / 2) * 16.0f / 9.0f;
  CHECK(f.classify(box({-half_width, 0, -50}, 2)) == Containment::intersecting);
  CHECK(f.classify(box({-half_width - 6, 0, -50}, 2)) == Containment::outside);
  CHECK(f.classify(box({-half_width + 6, 0, -50}, 2)) == Containment::inside);
  // A box around the eye crosses the near plane.
  CHECK(f.classify(box({0, 0, 0}, 10)) == Containment::intersecting);
  CHECK(f.may_see(box({0, 0, 0}, 10)));
}

TEST_CASE("LOD level is zero up close, grows by one per doubling and never decreases with distance") {
  const LodPolicy policy{100.0f, 4};
  CHECK(lod_level_for_distance(0.0f, policy) == 0);
  CHECK(lod_level_for_distance(99.0f, policy) == 0);
  CHECK(lod_level_for_distance(100.0f, policy) == 1);
  CHECK(lod_level_for_distance(199.0f, policy) == 1);
  CHECK(lod_level_for_distance(200.0f, policy) == 2);
  CHECK(lod_level_for_distance(1e9f, policy) == 4);
  int previous = 0;
  for (float d = 0.0f; d < 20000.0f; d += 7.3f) {
    const int level = lod_level_for_distance(d, policy);
    REQUIRE(level >= previous);
    REQUIRE(level <= policy.max_level);
    previous = level;
  }
  CHECK(lod_level_for_distance(std::nanf(""), policy) == 0);
}

TEST_CASE("supported LOD levels respect the grid's divisibility") {
  CHECK(supported_lod_levels(64, 5) == 5);   // stride 32 leaves 2 cells
  CHECK(supported_lod_levels(64, 3) == 3);
  CHECK(supported_lod_levels(64, 9) == 6);   // one cell
  CHECK(supported_lod_levels(96, 9) == 5);   // 96 = 3 * 32: stride 32 leaves 3 cells; 64 does not divide
  CHECK(supported_lod_levels(48, 9) == 4);   // 48 = 3 * 16
  CHECK(supported_lod_levels(6, 5) == 1);
  CHECK(supported_lod_levels(2, 5) == 1);
  CHECK(supported_lod_levels(63, 5) == 0);
}

TEST_CASE("fly controls move along the view, turn with the drag and keep above the sea") {
  Camera c;
  c.position = {0.0, 10.0, 0.0};
  FlyInput in;
  in.forward = true;
  apply_fly_input(c, in, 0.5, FlySettings{20.0f, 0.003f, 1.0f});
  CHECK(c.position.z == Approx(-10.0));
  CHECK(c.position.x == Approx(0.0).margin(1e-9));

  FlyInput drag;
  drag.look_dx_px = 100.0;  // dragging right turns right: the view swings toward +x
  apply_fly_input(c, drag, 0.0);
  CHECK(c.forward().x > 0.0f);
  drag.look_dx_px = 0.0;
  drag.look_dy_px = 100000.0;  // a huge drag down is clamped short of straight down
  apply_fly_input(c, drag, 0.0);
  CHECK(c.pitch_rad > -glm::half_pi<float>());
  CHECK(c.forward().y < -0.99f);

  FlyInput sink;
  sink.down = true;
  apply_fly_input(c, sink, 100.0, FlySettings{20.0f, 0.003f, 2.0f});
  CHECK(c.position.y == Approx(2.0));
}
