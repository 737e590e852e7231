// SceneParams: everything that defines an ocean scene, and the check that refuses bad values.
// A frame is a pure function of (SceneParams, t): nothing else may influence it. The sim, the
// codec's scene model and every front end hold a scene as this one struct.
#pragma once

#include "common/wave_band.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace ocean::model {

enum class SpectrumKind : std::uint8_t { phillips, jonswap };

// Directional spreading used with JONSWAP (Horvath 2015, section 5); each integrates to 1 over angle.
enum class SpreadingKind : std::uint8_t { cos2s, donelan_banner, hasselmann };

// The scene's ranges, which validate() enforces and the wire checks before decoding
// (protocol/field_checks.cpp). Depth, whose encodings differ, is checked by each.
inline constexpr int kMinSceneSize = 16;  // samples per side, a power of two
inline constexpr int kMaxSceneSize = 2048;
inline constexpr double kMinPatchM = 0.01;
inline constexpr double kMaxPatchM = 1e6;
inline constexpr double kMaxWindSpeedMps = 100.0;  // beyond any hurricane; more only overflows JONSWAP's constants
inline constexpr double kMaxWindDirDeg = 1e6;      // magnitude
inline constexpr double kMinFetchM = 1.0;
inline constexpr double kMaxFetchM = 1e8;
inline constexpr double kMaxAmplitude = 1e6;
inline constexpr double kMaxSmallWaveM = 1e6;
inline constexpr double kMaxChoppiness = 100.0;
inline constexpr double kMinGravityMps2 = 0.01;
inline constexpr double kMaxGravityMps2 = 1000.0;

struct SceneParams {
  int size_x = 256;          // N: samples along x, a power of two in [16, 2048]
  int size_z = 256;          // M: samples along z, a power of two in [16, 2048]
  double patch_x_m = 256.0;  // patch extent along x in metres, [0.01, 1e6]
  double patch_z_m = 256.0;  // patch extent along z in metres, [0.01, 1e6]

  SpectrumKind spectrum = SpectrumKind::phillips;
  SpreadingKind spreading = SpreadingKind::donelan_banner;  // JONSWAP only
  double wind_speed_mps = 10.0;  // U10 in m/s, [0, 100]; 0 = a flat sea
  double wind_dir_deg = 0.0;     // direction the wind blows towards, degrees from +x towards +z
  double fetch_m = 100000.0;     // JONSWAP fetch in metres, [1, 1e8]
  double amplitude = 1.0;        // scale on the spectrum's energy (Phillips A is derived from it), [0, 1e6]
  double depth_m = std::numeric_limits<double>::infinity();  // water depth, > 0; infinity = deep water
  double small_wave_m = 0.0;     // Tessendorf's suppression length l; 0 = half the grid spacing
  double choppiness = 0.0;       // lambda for horizontal displacement, [0, 100]
  double gravity_mps2 = 9.81;    // [0.01, 1000]
  std::uint64_t seed = 1;
  // The waves this realization keeps (cascade.hpp); whole by default. Not a weather parameter:
  // nobody sets it, a cascade derives it, and no message carries it.
  WaveBand band;
  bool operator==(const SceneParams&) const = default;
};

// Thrown for any parameter out of range; what() names the parameter, its value and the allowed range.
class ParamError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Empty when the parameters are usable, otherwise a message naming the first bad parameter.
std::string validate(const SceneParams& params);

// Deep water is infinity in a scene and 0 on the wire and in the codec's StreamConfig (no scene
// accepts a depth of 0). These two are that rule, for every conversion.
inline double wire_depth(double depth_m) { return std::isinf(depth_m) ? 0.0 : depth_m; }
inline double scene_depth(double wire_depth_m) {
  return wire_depth_m == 0.0 ? std::numeric_limits<double>::infinity() : wire_depth_m;
}

// Grid sizes: FFT lengths are powers of two within a range.
constexpr bool power_of_two_in(int n, int lo, int hi) { return n >= lo && n <= hi && (n & (n - 1)) == 0; }

}  // namespace ocean::model
