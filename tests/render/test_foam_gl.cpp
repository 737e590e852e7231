// The foam's lace on a real GL (EGL, llvmpipe here and in CI): a GL that cannot draw it still
// draws the foam and says so; the lace stays put as the eye moves, wherever it is.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "client/render/channel_upload.hpp"
#include "model/scene_params.hpp"
#include "sim/ocean.hpp"
#include "tests/render/render_gl_support.hpp"

using namespace ocean;
using test_render::context;
using test_render::draw_from_40_m;

namespace {

// A 20 m/s storm's single 64 m tile at t = 10 s, as a choppy stream carries it.
client::FrameChannels storm_tile() {
  model::SceneParams storm;
  storm.spectrum = model::SpectrumKind::jonswap;
  storm.wind_speed_mps = 20.0;
  storm.choppiness = 1.2;
  storm.size_x = storm.size_z = 64;
  storm.patch_x_m = storm.patch_z_m = 64.0;
  sim::Frame f;
  sim::Ocean(storm).evaluate(10.0, f, {true, true});
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.jacobian};
}

render::StreamLayout storm_layout() {
  render::StreamLayout layout;
  layout.tile = {64, 64.0f, 64.0f};
  return layout;
}

}  // namespace

TEST_CASE("a GL that cannot draw the foam's lace draws smooth foam, and says so on stderr", "[foam]") {
  context();
  const client::FrameChannels channels = storm_tile();
  const render::StreamLayout layout = storm_layout();
  std::vector<std::uint8_t> pictures[2];
  for (const bool without : {true, false}) {
    INFO("without the lace: " << without);
    render::RendererDesc desc;
    desc.without_foam_lace = without;
    desc.foam_only = true;
    render::Renderer renderer;
    // What init writes on stderr, from a file put in its place.
    std::fflush(stderr);
    const int saved = dup(2);
    FILE* captured = std::tmpfile();
    REQUIRE(captured);
    dup2(fileno(captured), 2);
    const bool ok = renderer.init(desc);
    std::fflush(stderr);
    dup2(saved, 2);
    close(saved);
    std::string said(4096, '\0');
    std::rewind(captured);
    said.resize(std::fread(said.data(), 1, said.size(), captured));
    std::fclose(captured);
    REQUIRE(ok);
    const std::string line = "the foam is drawn without its lace, as smooth patches (RendererDesc::without_foam_lace)";
    CHECK((said.find(line) != std::string::npos) == without);
    CHECK((renderer.foam_lace_unsupported() == "RendererDesc::without_foam_lace") == without);
    std::string warning;
    REQUIRE(render::apply_layout(renderer, layout, warning));
    render::Whitecaps whitecaps;
    whitecaps.set_wind({20.0, 0.0});
    for (int i = 0; i < 10; ++i) REQUIRE(render::upload_channels(renderer, channels, layout, whitecaps, 0.033));
    const auto picture = draw_from_40_m(renderer, -0.6f);
    int foamed = 0;
    for (std::size_t i = 0; i < picture.size(); i += 4) foamed += picture[i] > 64 && picture[i + 1] > 128;
    CHECK(foamed > 20);  // whitecaps either way, on the water
    pictures[without ? 0 : 1] = picture;
  }
  // The lace redistributes the same foam: the pictures differ, pixel by pixel.
  int differ = 0;
  for (std::size_t i = 0; i < pictures[0].size(); i += 4) differ += std::abs(pictures[0][i] - pictures[1][i]) > 16;
  CHECK(differ > 20);
}

TEST_CASE("the foam's lace stays put where the eye's coordinates wrap", "[foam]") {
  context();
  const client::FrameChannels channels = storm_tile();
  render::RendererDesc desc;
  desc.foam_only = true;
  render::Renderer renderer;
  REQUIRE(renderer.init(desc));
  REQUIRE(renderer.foam_lace_unsupported().empty());
  std::string warning;
  REQUIRE(render::apply_layout(renderer, storm_layout(), warning));
  render::Whitecaps whitecaps;
  whitecaps.set_wind({20.0, 30.0});  // the lace drawn out across the world's axes
  for (int i = 0; i < 10; ++i) REQUIRE(render::upload_channels(renderer, channels, storm_layout(), whitecaps, 0.033));
  render::OffscreenTarget target;
  std::string error;
  REQUIRE(target.create(160, 90, error));
  target.bind();
  // The foam term from 20 m up, eyes 0.1 m apart along x: the mean change of a pixel.
  const auto change = [&](double x) {
    std::vector<std::uint8_t> pictures[2];
    for (int k = 0; k < 2; ++k) {
      render::Camera camera;
      camera.position = {x + 0.1 * k, 20.0, 64.0 * 20 + 0.3};
      camera.pitch_rad = -0.9f;
      renderer.draw(camera, 160, 90, 10.0);
      pictures[k] = render::read_framebuffer_rgba(160, 90);
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < pictures[0].size(); i += 4) sum += std::abs(pictures[0][i] - pictures[1][i]);
    return sum / static_cast<double>(pictures[0].size() / 4);
  };
  // Across 1024 m, where the eye's offset in the vertex stage wraps, and where nothing wraps.
  const double across_wrap = change(64.0 * 16 - 0.05), elsewhere = change(64.0 * 11 - 0.05);
  INFO("mean change across the wrap " << across_wrap << ", elsewhere " << elsewhere);
  CHECK(elsewhere > 0.0);  // the foam moved with the eye: the measure sees a move
  CHECK(across_wrap < 2.0 * elsewhere + 0.5);
}
