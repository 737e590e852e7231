// Cube-map face conventions and what the renderer reads from the sky images.
#include <catch2/catch.hpp>

#include "client/render/cube_face.hpp"
#include "client/render/sky_faces.hpp"

using namespace ocean::render;

namespace {

SkyFaces uniform_faces(int size, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  SkyFaces f;
  f.size = size;
  for (auto& face : f.rgba) {
    face.resize(std::size_t(size) * size * 4);
    for (std::size_t i = 0; i < face.size(); i += 4) {
      face[i] = r;
      face[i + 1] = g;
      face[i + 2] = b;
      face[i + 3] = 255;
    }
  }
  return f;
}

}  // namespace

TEST_CASE("cube face centres look along the six axes") {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) CHECK(glm::length(cube_face_direction(f, 0.5f, 0.5f) - axes[f]) < 1e-6f);
  // The top row (t = 0) of a side face looks up.
  for (int f : {0, 1, 4, 5}) CHECK(cube_face_direction(f, 0.5f, 0.1f).y > 0.5f);
}

TEST_CASE("cube_face_texel inverts cube_face_direction") {
  for (int f = 0; f < 6; ++f) {
    for (float s : {0.05f, 0.3f, 0.5f, 0.8f, 0.95f}) {
      for (float t : {0.1f, 0.45f, 0.9f}) {
        const CubeTexel back = cube_face_texel(cube_face_direction(f, s, t));
        INFO("face " << f << " s " << s << " t " << t);
        CHECK(back.face == f);
        CHECK(back.s == Approx(s).margin(1e-5));
        CHECK(back.t == Approx(t).margin(1e-5));
      }
    }
  }
}

TEST_CASE("the sun is found at the brightest spot of the sky") {
  SkyFaces faces = uniform_faces(32, 90, 140, 200);
  const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.3f, -0.85f));
  const CubeTexel t = cube_face_texel(sun);
  const int x = int(t.s * 32), y = int(t.t * 32);
  std::uint8_t* p = &faces.rgba[t.face][(std::size_t(y) * 32 + x) * 4];
  p[0] = p[1] = p[2] = 255;
  // One texel is ~1/32 of a face: the estimate is within a texel's angle.
  CHECK(glm::dot(estimate_sun_direction(faces), sun) > std::cos(0.05f));
  CHECK(estimate_sun_direction(SkyFaces{}) == glm::vec3(0, 1, 0));
}

TEST_CASE("the horizon ring samples the sky colour around the horizon") {
  const SkyFaces faces = uniform_faces(16, 51, 102, 204);
  for (const glm::vec3& c : horizon_ring(faces, 0.02f)) CHECK(glm::length(c - glm::vec3(0.2f, 0.4f, 0.8f)) < 1e-6f);
  SkyFaces split = uniform_faces(16, 0, 0, 0);
  split.rgba[0].assign(split.rgba[0].size(), 255);  // only +x is white
  const auto ring = horizon_ring(split, 0.02f);
  CHECK(ring[kHorizonRingSize / 2].r == Approx(1.0f));  // azimuth 0 looks along +x
  CHECK(ring[0].r == Approx(0.0f));                      // azimuth -pi looks along -x
}

TEST_CASE("loading sky faces from a missing folder names the file") {
  SkyFaces faces;
  std::string error;
  CHECK_FALSE(load_sky_faces("/nonexistent/sky", faces, error));
  CHECK(error.find("/nonexistent/sky/px.png") != std::string::npos);
}
