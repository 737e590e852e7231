// ocean-viewer end to end, in-process: the headless front end against StreamTestServer renders
// sky above and water below from streamed frames; --record writes what arrived; a missing server
// is a clear error; a restarted server (even with another grid) is reconnected to and followed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include "client/viewer/headless_context.hpp"
#include "client/viewer/stream_view.hpp"
#include "client/viewer/viewer_run.hpp"
#include "stream_test_server.hpp"

using namespace ocean;
using namespace ocean::viewer;

namespace {

// Generous: the suite shares two cores with everyone's builds.
constexpr double kPatienceS = 30.0;

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("ocean_test_viewer_" + std::to_string(::getpid()) + "_" + name);
}

ViewerOptions options_for(std::uint16_t port) {
  ViewerOptions o;
  o.host = "127.0.0.1";
  o.port = std::to_string(port);
  o.headless = true;
  o.width = 320;
  o.height = 180;
  o.frames = 40;
  o.first_frame_timeout_s = kPatienceS;
  return o;
}

struct Rgb {
  double r = 0, g = 0, b = 0;
};

Rgb mean_rgb(const unsigned char* rgba, int width, int row_begin, int row_end) {
  Rgb m;
  for (int y = row_begin; y < row_end; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = rgba + 4 * (static_cast<std::size_t>(y) * width + x);
      m.r += p[0], m.g += p[1], m.b += p[2];
    }
  const double n = 255.0 * (row_end - row_begin) * width;
  return {m.r / n, m.g / n, m.b / n};
}

template <typename Done>
bool wait_until(Done done, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

}  // namespace

TEST_CASE("the headless viewer renders a streamed sea: sky above, water below") {
  viewer::test::StreamTestServer server(0, "mobile");  // mobile: 64 x 64 at 30 Hz
  ViewerOptions o = options_for(server.port());
  const auto png = temp_path("shot.png");
  o.screenshot = png.string();
  ViewerSummary summary;
  std::string error;
  REQUIRE(run_headless(o, summary, error) == 0);
  INFO(summary_json(summary));
  CHECK(summary.frames == o.frames);
  CHECK(summary.net.frames_received > 0);
  CHECK(summary.uploads > 0);
  CHECK(summary.grid == 64);
  CHECK(summary.profile == "mobile");
  CHECK(summary.net.bytes_in > 0);
  CHECK(summary.cpu_ms_per_frame > 0.0);

  int w = 0, h = 0, channels = 0;
  unsigned char* rgba = stbi_load(png.string().c_str(), &w, &h, &channels, 4);
  REQUIRE(rgba != nullptr);
  REQUIRE(w == o.width);
  REQUIRE(h == o.height);
  const Rgb sky = mean_rgb(rgba, w, 0, h / 10);
  const Rgb water = mean_rgb(rgba, w, h * 8 / 10, h);
  stbi_image_free(rgba);
  std::filesystem::remove(png);
  INFO("sky " << sky.r << " " << sky.g << " " << sky.b << "; water " << water.r << " " << water.g << " " << water.b);
  CHECK(sky.b > 0.6);
  CHECK(sky.b >= sky.r);
  CHECK(water.r + water.g + water.b < 0.7 * (sky.r + sky.g + sky.b));
  CHECK(water.b > water.r);
}

TEST_CASE("recording (--record) writes the heights of every received frame") {
  viewer::test::StreamTestServer server(0, "lite");  // lite: 32 x 32 at 15 Hz
  ViewerOptions o = options_for(server.port());
  const auto npy = temp_path("frames.npy");
  o.record_path = npy.string();
  o.frames = 30;
  ViewerSummary summary;
  std::string error;
  REQUIRE(run_headless(o, summary, error) == 0);
  REQUIRE(summary.net.frames_recorded > 0);
  CHECK(summary.net.frames_recorded == summary.net.frames_received);

  std::ifstream in(npy, std::ios::binary);
  REQUIRE(in);
  std::string header(128, '\0');
  in.read(header.data(), 128);
  const std::string shape = "(" + std::to_string(summary.net.frames_recorded) + ", 32, 32)";
  INFO(header);
  CHECK(header.find(shape) != std::string::npos);
  in.seekg(0, std::ios::end);
  CHECK(static_cast<std::uint64_t>(in.tellg()) == 128 + summary.net.frames_recorded * 32 * 32 * sizeof(float));
  in.close();
  // Beside it, the tick of every recorded frame (int64), rising, one per frame.
  const auto ticks_npy = temp_path("frames.ticks.npy");
  std::ifstream ticks(ticks_npy, std::ios::binary);
  REQUIRE(ticks);
  ticks.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(ticks.tellg());
  REQUIRE(size >= 128);
  const std::uint64_t count = (size - 128) / sizeof(std::int64_t);
  CHECK(count == summary.net.frames_recorded);
  ticks.seekg(128);
  std::int64_t previous = -1;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::int64_t tick = 0;
    ticks.read(reinterpret_cast<char*>(&tick), sizeof tick);
    CHECK(tick > previous);
    previous = tick;
  }
  ticks.close();
  std::filesystem::remove(npy);
  std::filesystem::remove(ticks_npy);
}

TEST_CASE("no server: the headless viewer gives up after its timeout with a reason") {
  std::uint16_t port = 0;
  {
    viewer::test::StreamTestServer probe(0, "mobile");
    port = probe.port();
  }  // closed: nothing listens there now
  ViewerOptions o = options_for(port);
  o.first_frame_timeout_s = 1.0;
  ViewerSummary summary;
  std::string error;
  CHECK(run_headless(o, summary, error) == kExitNoServer);  // 3: nothing answered
  CHECK(error.find("no frame from 127.0.0.1:" + std::to_string(port)) != std::string::npos);
  CHECK(error.find("--first-frame-timeout") != std::string::npos);
}

TEST_CASE("the viewer reconnects to a restarted server, holds the picture meanwhile, and follows a new grid") {
  HeadlessContext context;
  std::string error;
  REQUIRE(context.create(error));
  StreamView view;
  REQUIRE(view.init({}, {}, error));

  auto server = std::make_unique<viewer::test::StreamTestServer>(0, "mobile");
  const std::uint16_t port = server->port();
  NetworkThreadConfig config;
  REQUIRE(make_network_config(options_for(port), config, error));
  config.connection.reconnect_max_s = 0.5;
  NetworkThread net(config);
  net.start();
  // The byte count and rate the HUD shows stay sane across the restart: the count never goes back
  // (it did: the ended session was counted twice until the next one began, then the rate underflowed).
  std::uint64_t bytes_seen = 0;
  bool bytes_went_back = false;
  double max_kbps = 0.0;
  const auto render = [&] {
    const NetworkStats stats = net.stats();
    bytes_went_back = bytes_went_back || stats.bytes_in < bytes_seen;
    bytes_seen = std::max(bytes_seen, stats.bytes_in);
    max_kbps = std::max(max_kbps, stats.kbps);
    return view.update(net, client::ClientConnection::now_s());
  };

  REQUIRE(wait_until([&] { return render() && view.uploads() >= 10; }, kPatienceS));
  CHECK(view.shape().grid == 64);
  const std::uint64_t received_before = net.frames_received();

  server.reset();  // the server goes away ...
  const std::uint64_t uploads_before = view.uploads();
  for (int i = 0; i < 20; ++i) {
    REQUIRE(render());  // ... and rendering goes on with what it has
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  CHECK(view.uploads() >= uploads_before);

  server = std::make_unique<viewer::test::StreamTestServer>(port, "lite");  // ... and comes back as lite: 32 x 32
  REQUIRE(wait_until([&] { return render() && net.frames_received() >= received_before + 10 && view.shape().grid == 32; },
                     kPatienceS));
  const std::uint64_t uploads_after_restart = view.uploads();
  REQUIRE(wait_until([&] { return render() && view.uploads() >= uploads_after_restart + 5; }, kPatienceS));
  CHECK(view.shape().profile == "lite");
  CHECK(view.grid_changes() == 2);
  CHECK(view.renderer().grid_n() == 32);
  CHECK(server->sessions() == 1);
  net.stop();
  CHECK(net.stats().connects >= 2);
  CHECK_FALSE(bytes_went_back);
  CHECK(max_kbps < 1e5);  // the test streams are a few hundred kbit/s
}
