// What the GL render tests share: one headless context for the whole executable, and a small
// picture of the sea from 40 m up.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "client/render/framebuffer_readback.hpp"
#include "client/render/offscreen_target.hpp"
#include "client/render/renderer.hpp"
#include "client/viewer/headless_context.hpp"

namespace ocean::test_render {

// One context for the whole executable; EGL display set-up is the slow part.
inline viewer::HeadlessContext& context() {
  static viewer::HeadlessContext ctx;
  static std::string error;
  static const bool ok = ctx.create(error);
  if (!ok)
    FAIL("cannot create a headless OpenGL ES 2 context through EGL: " << error
         << ". These tests need an EGL driver; Mesa's llvmpipe (CPU) is enough.");
  return ctx;
}

// A 160 x 90 picture of the sea from 40 m up at t = 10 s.
inline std::vector<std::uint8_t> draw_from_40_m(render::Renderer& renderer, float pitch_rad) {
  render::OffscreenTarget target;
  std::string error;
  REQUIRE(target.create(160, 90, error));
  target.bind();
  render::Camera camera;
  camera.position = {0.3, 40.0, 0.7};
  camera.pitch_rad = pitch_rad;
  renderer.draw(camera, 160, 90, 10.0);
  CHECK(glGetError() == GL_NO_ERROR);
  return render::read_framebuffer_rgba(160, 90);
}

}  // namespace ocean::test_render
