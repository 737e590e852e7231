// A frame is a pure function of (params, t): no dependence on earlier ticks, identical bits in
// another process (ocean-simdump), and sensitive to every input that should change it.
#include "frame_hash.hpp"
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

using namespace ocean::sim;
using ocean::model::SpectrumKind;
using ocean::model::SpreadingKind;

namespace {

bool same_bits(const Frame& a, const Frame& b) {
  const auto same = [](const std::vector<float>& x, const std::vector<float>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0;
  };
  return a.n_x == b.n_x && a.n_z == b.n_z && same(a.height, b.height) && same(a.slope_x, b.slope_x) &&
         same(a.slope_z, b.slope_z) && same(a.disp_x, b.disp_x) && same(a.disp_z, b.disp_z) &&
         same(a.jacobian, b.jacobian);
}

// ocean_add_test sets OCEAN_BUILD_DIR for CTest; run by hand, the tool is found next to this test.
std::string simdump_path() {
  if (const char* build = std::getenv("OCEAN_BUILD_DIR")) return std::string(build) + "/sim/ocean-simdump";
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  REQUIRE_FALSE(ec);
  return (self.parent_path().parent_path().parent_path() / "sim/ocean-simdump").string();
}

std::string run_simdump(const std::string& args) {
  const std::string command = simdump_path() + " --hash " + args;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::array<char, 128> buf{};
  std::string out;
  while (std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int status = pclose(pipe);
  INFO(command);
  REQUIRE(status == 0);
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

TEST_CASE("a frame does not depend on the frames evaluated before it", "[sim][determinism]") {
  SceneParams p;
  p.size_x = p.size_z = 128;
  p.choppiness = 1.0;
  p.spectrum = SpectrumKind::jonswap;
  Ocean warm(p), fresh(p);
  Frame a, b, scratch;
  warm.evaluate(1.0, scratch, FrameRequest{true, true});
  warm.evaluate_band(9000.0, 32, 32, scratch, FrameRequest{true, true});
  warm.evaluate(-3.0, scratch);
  warm.evaluate(7.5, a, FrameRequest{true, true});
  fresh.evaluate(7.5, b, FrameRequest{true, true});
  CHECK(same_bits(a, b));
  warm.evaluate_band(7.5, 32, 64, a);
  fresh.evaluate_band(7.5, 32, 64, b);
  CHECK(same_bits(a, b));
  // ... and it does change with t.
  fresh.evaluate(7.5 + 1e-3, b, FrameRequest{true, true});
  CHECK_FALSE(same_bits(a, b));
}

TEST_CASE("ocean-simdump in two processes computes the same bits as this process", "[sim][determinism]") {
  struct Case {
    std::string args;
    SceneParams params;
    double t;
    int band;
    FrameRequest request;
  };
  SceneParams choppy_jonswap;
  choppy_jonswap.size_x = choppy_jonswap.size_z = 128;
  choppy_jonswap.spectrum = SpectrumKind::jonswap;
  choppy_jonswap.depth_m = 30.0;
  choppy_jonswap.seed = 7;
  choppy_jonswap.choppiness = 1.0;  // simdump's --choppy uses --lambda, default 1
  const Case cases[] = {
      {"--time 3.25", SceneParams{}, 3.25, 0, FrameRequest{true, false}},
      {"--time 12.5 --size 128 --band 64 --choppy --seed 7 --spectrum jonswap --depth 30", choppy_jonswap, 12.5, 64,
       FrameRequest{true, true}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const std::string first = run_simdump(c.args);
    const std::string second = run_simdump(c.args);
    CHECK(first.size() == 16);
    CHECK(first == second);
    Ocean ocean(c.params);
    Frame f;
    if (c.band)
      ocean.evaluate_band(c.t, c.band, c.band, f, c.request);
    else
      ocean.evaluate(c.t, f, c.request);
    CHECK(first == hex(frame_hash(f)));
  }
  CHECK(run_simdump("--time 3.25 --seed 2") != run_simdump("--time 3.25"));
}

TEST_CASE("the frame hash covers every field", "[sim][determinism]") {
  SceneParams p;
  p.size_x = p.size_z = 16;
  p.choppiness = 0.5;
  Ocean ocean(p);
  Frame f;
  ocean.evaluate(1.0, f, FrameRequest{true, true});
  const std::uint64_t h = frame_hash(f);
  for (auto field : {&Frame::height, &Frame::slope_x, &Frame::slope_z, &Frame::disp_x, &Frame::disp_z,
                     &Frame::jacobian}) {
    Frame g = f;
    std::vector<float>& v = g.*field;
    v[v.size() / 2] = std::nextafter(v[v.size() / 2], 10.0f);
    CHECK(frame_hash(g) != h);
  }
}

TEST_CASE("Oceans built and evaluated on several threads at once give the same frames", "[sim][determinism]") {
  // FFTW's planner is global; plan creation and destruction must be serialised (see c2r_transform.cpp).
  SceneParams p;
  p.size_x = p.size_z = 64;
  p.choppiness = 0.6;
  Frame reference;
  Ocean(p).evaluate_band(4.0, 32, 32, reference, FrameRequest{true, true});
  std::vector<Frame> frames(4);
  std::vector<std::thread> threads;
  for (Frame& f : frames)
    threads.emplace_back([&p, &f] {
      for (int round = 0; round < 5; ++round) {
        Ocean ocean(p);
        ocean.evaluate(1.0, f);
        ocean.evaluate_band(4.0, 32, 32, f, FrameRequest{true, true});
      }
    });
  for (std::thread& t : threads) t.join();
  for (const Frame& f : frames) CHECK(same_bits(f, reference));
}
