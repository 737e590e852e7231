// FoamMemory: foam follows a fold at once and fades over about a second after it, never before.
#include "client/render/foam_memory.hpp"

#include <catch2/catch.hpp>

#include <vector>

using ocean::render::FoamMemory;

TEST_CASE("foam memory takes a fold at once and lets it go at its rate", "[foam]") {
  FoamMemory foam(0.2f);
  std::vector<float> j = {1.0f, 0.9f};
  CHECK(foam.update(j, 0.1) == j);  // the first frame is shown as it is
  j = {0.3f, 0.9f};
  CHECK(foam.update(j, 0.1)[0] == Approx(0.3f));  // a fold shows in the frame it appears
  j = {1.0f, 0.9f};
  const auto& after = foam.update(j, 0.5);
  CHECK(after[0] == Approx(0.4f));  // 0.3 + 0.2 * 0.5: still foaming
  CHECK(after[1] == Approx(0.9f));  // untouched samples follow the stream exactly
  for (int i = 0; i < 10; ++i) foam.update(j, 0.5);
  CHECK(foam.update(j, 0.5)[0] == Approx(1.0f));  // gone once recovered, never above the stream
}

TEST_CASE("foam memory clamps a stall and starts over on a new grid", "[foam]") {
  FoamMemory foam(0.2f);
  foam.update(std::vector<float>{0.2f}, 0.0);
  CHECK(foam.update(std::vector<float>{1.0f}, 30.0)[0] == Approx(0.4f));  // dt clamped to 1 s
  CHECK(foam.update(std::vector<float>{1.0f, 0.5f}, 0.1) == std::vector<float>{1.0f, 0.5f});
}
