// Every bad parameter is refused with a message naming the parameter, the value and the allowed range.
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace ocean::sim;
using ocean::model::SpectrumKind;
using ocean::model::SpreadingKind;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

struct BadCase {
  const char* name;
  std::function<void(SceneParams&)> spoil;
  const char* value;    // as the message must print it
  const char* allowed;  // a fragment of the allowed range
};

std::string ocean_error(const SceneParams& p) {
  try {
    Ocean ocean(p);
  } catch (const ParamError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("the defaults and deep water are valid", "[sim][params]") {
  SceneParams p;
  CHECK(validate(p).empty());
  CHECK(std::isinf(p.depth_m));
  p.spectrum = SpectrumKind::jonswap;
  p.spreading = SpreadingKind::hasselmann;
  p.wind_speed_mps = 0.0;
  p.size_x = 16;
  p.size_z = 2048;
  CHECK(validate(p).empty());
}

TEST_CASE("each bad scene parameter is named with its value and range", "[sim][params]") {
  const BadCase cases[] = {
      {"size_x", [](SceneParams& p) { p.size_x = 100; }, "100", "power of two in [16, 2048]"},
      {"size_x", [](SceneParams& p) { p.size_x = 8; }, "8", "power of two in [16, 2048]"},
      {"size_x", [](SceneParams& p) { p.size_x = 4096; }, "4096", "power of two in [16, 2048]"},
      {"size_z", [](SceneParams& p) { p.size_z = 0; }, "0", "power of two in [16, 2048]"},
      {"size_z", [](SceneParams& p) { p.size_z = -256; }, "-256", "power of two in [16, 2048]"},
      {"patch_x_m", [](SceneParams& p) { p.patch_x_m = 0.0; }, "0", "[0.01, 1e6] metres"},
      {"patch_z_m", [](SceneParams& p) { p.patch_z_m = not_a_number; }, "nan", "[0.01, 1e6] metres"},
      {"patch_z_m", [](SceneParams& p) { p.patch_z_m = -3.5; }, "-3.5", "[0.01, 1e6] metres"},
      {"wind_speed_mps", [](SceneParams& p) { p.wind_speed_mps = -1.0; }, "-1", "[0, 100] m/s"},
      {"wind_speed_mps", [](SceneParams& p) { p.wind_speed_mps = not_a_number; }, "nan", "[0, 100] m/s"},
      {"wind_speed_mps", [](SceneParams& p) { p.wind_speed_mps = inf; }, "inf", "[0, 100] m/s"},
      {"wind_dir_deg", [](SceneParams& p) { p.wind_dir_deg = not_a_number; }, "nan", "finite angle"},
      {"fetch_m", [](SceneParams& p) { p.fetch_m = 0.0; }, "0", "[1, 1e8] metres"},
      {"amplitude", [](SceneParams& p) { p.amplitude = -0.5; }, "-0.5", "[0, 1e6]"},
      {"amplitude", [](SceneParams& p) { p.amplitude = not_a_number; }, "nan", "[0, 1e6]"},
      {"depth_m", [](SceneParams& p) { p.depth_m = 0.0; }, "0", "(0, inf] metres"},
      {"depth_m", [](SceneParams& p) { p.depth_m = -5.0; }, "-5", "(0, inf] metres"},
      {"depth_m", [](SceneParams& p) { p.depth_m = not_a_number; }, "nan", "(0, inf] metres"},
      {"small_wave_m", [](SceneParams& p) { p.small_wave_m = -0.1; }, "-0.1", "[0, 1e6] metres"},
      {"choppiness", [](SceneParams& p) { p.choppiness = not_a_number; }, "nan", "[0, 100]"},
      {"choppiness", [](SceneParams& p) { p.choppiness = -1.0; }, "-1", "[0, 100]"},
      {"gravity_mps2", [](SceneParams& p) { p.gravity_mps2 = 0.0; }, "0", "[0.01, 1000] m/s^2"},
      {"spectrum", [](SceneParams& p) { p.spectrum = static_cast<SpectrumKind>(7); }, "7", "phillips (0) or jonswap"},
      {"spreading", [](SceneParams& p) { p.spreading = static_cast<SpreadingKind>(9); }, "9", "cos2s (0)"},
  };
  for (const BadCase& c : cases) {
    SceneParams p;
    c.spoil(p);
    const std::string message = validate(p);
    CAPTURE(c.name, c.value, message);
    CHECK(message.rfind(std::string(c.name) + " = " + c.value + " is invalid", 0) == 0);
    CHECK(message.find(c.allowed) != std::string::npos);
    CHECK(ocean_error(p) == message);
  }
}

TEST_CASE("bad band sizes and times are refused by name", "[sim][params]") {
  SceneParams p;
  p.size_x = 128;
  p.size_z = 64;
  Ocean ocean(p);
  Frame f;
  const auto band_error = [&](int n_x, int n_z) -> std::string {
    try {
      ocean.evaluate_band(0.0, n_x, n_z, f);
    } catch (const ParamError& e) {
      return e.what();
    }
    return {};
  };
  CHECK(band_error(48, 32) == "band n_x = 48 is invalid: allowed a power of two in [16, size_x = 128]");
  CHECK(band_error(256, 32) == "band n_x = 256 is invalid: allowed a power of two in [16, size_x = 128]");
  CHECK(band_error(8, 32) == "band n_x = 8 is invalid: allowed a power of two in [16, size_x = 128]");
  CHECK(band_error(32, 128) == "band n_z = 128 is invalid: allowed a power of two in [16, size_z = 64]");
  CHECK(band_error(32, 0) == "band n_z = 0 is invalid: allowed a power of two in [16, size_z = 64]");
  CHECK(band_error(32, 32).empty());

  const auto time_error = [&](double t) -> std::string {
    try {
      ocean.evaluate(t, f);
    } catch (const ParamError& e) {
      return e.what();
    }
    return {};
  };
  CHECK(time_error(not_a_number) == "t = nan is invalid: allowed finite with |t| <= 1e+09 s");
  CHECK(time_error(-inf) == "t = -inf is invalid: allowed finite with |t| <= 1e+09 s");
  CHECK(time_error(2e9) == "t = 2e+09 is invalid: allowed finite with |t| <= 1e+09 s");
  CHECK(time_error(-1e9).empty());
}
