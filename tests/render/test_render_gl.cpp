// One real frame through EGL (llvmpipe here and in CI): every shader compiles and links, and the
// synthetic sea renders as "sky above, water below". No GL context is a failure, not a skip.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "client/render/framebuffer_readback.hpp"
#include "client/render/gl_program.hpp"
#include "client/render/hud_overlay.hpp"
#include "client/render/offscreen_target.hpp"
#include "client/render/renderer.hpp"
#include "client/render/shader_sources.hpp"
#include "client/viewer/headless_context.hpp"
#include "client/viewer/synthetic_sea.hpp"

using namespace ocean;

namespace {

constexpr int kWidth = 320, kHeight = 180;

// One context for the whole executable; EGL display set-up is the slow part.
viewer::HeadlessContext& context() {
  static viewer::HeadlessContext ctx;
  static std::string error;
  static const bool ok = ctx.create(error);
  if (!ok)
    FAIL("cannot create a headless OpenGL ES 2 context through EGL: " << error
         << ". These tests need an EGL driver; Mesa's llvmpipe (CPU) is enough.");
  return ctx;
}

struct RegionStats {
  glm::dvec3 mean{0.0};
  double luminance_variance = 0.0;
};

RegionStats region(const std::vector<std::uint8_t>& rgba, int row_begin, int row_end) {
  RegionStats s;
  double sum_l = 0.0, sum_l2 = 0.0;
  const int count = (row_end - row_begin) * kWidth;
  for (int y = row_begin; y < row_end; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::uint8_t* p = &rgba[(std::size_t(y) * kWidth + x) * 4];
      const glm::dvec3 c = glm::dvec3(p[0], p[1], p[2]) / 255.0;
      s.mean += c;
      const double l = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
      sum_l += l;
      sum_l2 += l * l;
    }
  }
  s.mean /= count;
  s.luminance_variance = sum_l2 / count - (sum_l / count) * (sum_l / count);
  return s;
}

std::vector<std::uint8_t> render_sea(bool choppy, bool hud, render::DrawStats* stats = nullptr) {
  context();
  render::Renderer renderer;
  REQUIRE(renderer.init({}));
  INFO(renderer.error());
  REQUIRE(renderer.set_grid(64, 128.0f, 128.0f));
  viewer::SyntheticSeaParams params;
  params.choppy = choppy;
  const viewer::SyntheticSea sea(params);
  viewer::SeaFrame frame;
  sea.evaluate(2.0, frame);
  REQUIRE(renderer.upload_frame(frame.height.data(), frame.slope_x.data(), frame.slope_z.data(),
                                choppy ? frame.disp_x.data() : nullptr, choppy ? frame.disp_z.data() : nullptr,
                                choppy ? frame.jacobian.data() : nullptr));
  render::OffscreenTarget target;
  std::string error;
  REQUIRE(target.create(kWidth, kHeight, error));
  target.bind();
  render::Camera camera;
  camera.position = {0.0, 10.0, 0.0};
  camera.pitch_rad = -0.1f;
  renderer.draw(camera, kWidth, kHeight, 2.0);
  if (hud) {
    render::HudOverlay overlay;
    REQUIRE(overlay.init(error));
    overlay.draw({60.0, 512.0, 40.0, 0.5, "mobile", ""}, kWidth, kHeight);
  }
  CHECK(glGetError() == GL_NO_ERROR);
  if (stats) *stats = renderer.last_stats();
  return render::read_framebuffer_rgba(kWidth, kHeight);
}

}  // namespace

TEST_CASE("a headless EGL context with OpenGL ES 2 can be created") {
  INFO(context().description());
  CHECK(glGetString(GL_VERSION) != nullptr);
}

TEST_CASE("every shader compiles and links") {
  context();
  namespace src = render::shader_source;
  const struct {
    const char* name;
    const char* vs;
    const char* fs;
  } programs[] = {{"ocean", src::ocean_vert, src::ocean_frag},
                  {"sky", src::sky_vert, src::sky_frag},
                  {"hud", src::hud_vert, src::hud_frag}};
  for (const auto& p : programs) {
    std::string error;
    const GLuint program = render::build_program(p.name, p.vs, p.fs, {}, error);
    INFO(error);
    CHECK(program != 0);
    glDeleteProgram(program);
  }
  std::string error;
  CHECK(render::build_program("broken", src::sky_vert, "#version 100\nvoid main() { undefined_call(); }", {}, error) == 0);
  CHECK(error.find("broken fragment shader failed to compile") != std::string::npos);
}

TEST_CASE("the synthetic sea renders as sky above and water below") {
  render::DrawStats stats;
  const auto pixels = render_sea(true, false, &stats);
  CHECK(stats.tiles_drawn > 10);
  CHECK(stats.tiles_culled > 0);
  const RegionStats sky = region(pixels, 0, kHeight / 10);
  const RegionStats water = region(pixels, kHeight * 8 / 10, kHeight);
  INFO("sky mean " << sky.mean.r << " " << sky.mean.g << " " << sky.mean.b << "; water mean " << water.mean.r << " "
                   << water.mean.g << " " << water.mean.b << " variance " << water.luminance_variance);
  // Sky: bright and blue-white.
  CHECK(sky.mean.b > 0.6);
  CHECK(sky.mean.b >= sky.mean.r);
  // Water: darker than the sky, and bluer/greener than red.
  CHECK(water.mean.r + water.mean.g + water.mean.b < 0.7 * (sky.mean.r + sky.mean.g + sky.mean.b));
  CHECK(water.mean.b > water.mean.r);
  CHECK(water.mean.g > water.mean.r);
  // Waves: the lower half is not one flat colour.
  CHECK(region(pixels, kHeight / 2, kHeight).luminance_variance > 1e-4);
}

TEST_CASE("a sea without chop (heights and slopes only) also renders") {
  const auto pixels = render_sea(false, false);
  const RegionStats water = region(pixels, kHeight * 8 / 10, kHeight);
  CHECK(water.mean.b > water.mean.r);
  CHECK(water.luminance_variance > 1e-5);
}

TEST_CASE("the HUD draws text over the scene in the top-left corner") {
  const auto plain = render_sea(true, false);
  const auto with_hud = render_sea(true, true);
  int changed_top_left = 0, changed_elsewhere = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = (std::size_t(y) * kWidth + x) * 4;
      const bool differs = plain[i] != with_hud[i] || plain[i + 1] != with_hud[i + 1] || plain[i + 2] != with_hud[i + 2];
      if (!differs) continue;
      (x < kWidth / 2 && y < kHeight / 2 ? changed_top_left : changed_elsewhere)++;
    }
  }
  CHECK(changed_top_left > 200);
  CHECK(changed_elsewhere == 0);
}

TEST_CASE("renderer preconditions fail with a reason") {
  context();
  render::Renderer renderer;
  REQUIRE(renderer.init({}));
  CHECK_FALSE(renderer.upload_frame(render::FrameStreams{}));
  CHECK(renderer.error().find("before set_grid") != std::string::npos);
  CHECK_FALSE(renderer.set_grid(1, 100.0f, 100.0f));
  CHECK(renderer.error().find("n = 1") != std::string::npos);
  CHECK_FALSE(renderer.set_grid(64, 0.0f, 100.0f));
  CHECK(renderer.error().find("patch size") != std::string::npos);
  REQUIRE(renderer.set_grid(16, 50.0f, 50.0f));
  CHECK_FALSE(renderer.upload_frame(render::FrameStreams{}));
  CHECK(renderer.error().find("height is required") != std::string::npos);
  render::RendererDesc bad_sky;
  bad_sky.sky_dir = "/nonexistent/sky";
  render::Renderer other;
  CHECK_FALSE(other.init(bad_sky));
  CHECK(other.error().find("/nonexistent/sky/px.png") != std::string::npos);
}
