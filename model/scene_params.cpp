// validate(): the range check of every SceneParams field, with messages a person can act on.
#include "scene_params.hpp"

#include "param_message.hpp"
#include "scene_names.hpp"

#include <cmath>

namespace ocean::model {
namespace {

// "phillips (0) or jonswap (1)": the valid names with the enum values a bad value is shown against.
std::string numbered(std::vector<std::string> names) {
  for (std::size_t i = 0; i < names.size(); ++i) names[i] += " (" + std::to_string(i) + ")";
  return join_names(names, ", ", " or ");
}

}  // namespace

std::string validate(const SceneParams& p) {
  if (!power_of_two_in(p.size_x, kMinSceneSize, kMaxSceneSize))
    return bad_param("size_x", p.size_x, "a power of two in [16, 2048]");
  if (!power_of_two_in(p.size_z, kMinSceneSize, kMaxSceneSize))
    return bad_param("size_z", p.size_z, "a power of two in [16, 2048]");
  if (!(std::isfinite(p.patch_x_m) && p.patch_x_m >= kMinPatchM && p.patch_x_m <= kMaxPatchM))
    return bad_param("patch_x_m", p.patch_x_m, "[0.01, 1e6] metres");
  if (!(std::isfinite(p.patch_z_m) && p.patch_z_m >= kMinPatchM && p.patch_z_m <= kMaxPatchM))
    return bad_param("patch_z_m", p.patch_z_m, "[0.01, 1e6] metres");
  if (spectrum_name(p.spectrum).empty())
    return bad_param("spectrum", static_cast<int>(p.spectrum), numbered(spectrum_names()));
  if (spreading_name(p.spreading).empty())
    return bad_param("spreading", static_cast<int>(p.spreading), numbered(spreading_names()));
  if (!(p.wind_speed_mps >= 0.0 && p.wind_speed_mps <= kMaxWindSpeedMps))
    return bad_param("wind_speed_mps", p.wind_speed_mps, "[0, 100] m/s");
  if (!std::isfinite(p.wind_dir_deg) || std::fabs(p.wind_dir_deg) > kMaxWindDirDeg)
    return bad_param("wind_dir_deg", p.wind_dir_deg, "a finite angle in [-1e6, 1e6] degrees");
  if (!(std::isfinite(p.fetch_m) && p.fetch_m >= kMinFetchM && p.fetch_m <= kMaxFetchM))
    return bad_param("fetch_m", p.fetch_m, "[1, 1e8] metres");
  if (!(std::isfinite(p.amplitude) && p.amplitude >= 0.0 && p.amplitude <= kMaxAmplitude))
    return bad_param("amplitude", p.amplitude, "[0, 1e6]");
  if (!(p.depth_m > 0.0))  // also refuses NaN; +infinity means deep water
    return bad_param("depth_m", p.depth_m, "(0, inf] metres (inf = deep water)");
  if (!(std::isfinite(p.small_wave_m) && p.small_wave_m >= 0.0 && p.small_wave_m <= kMaxSmallWaveM))
    return bad_param("small_wave_m", p.small_wave_m, "[0, 1e6] metres (0 = half the grid spacing)");
  if (!(std::isfinite(p.choppiness) && p.choppiness >= 0.0 && p.choppiness <= kMaxChoppiness))
    return bad_param("choppiness", p.choppiness, "[0, 100]");
  if (!(std::isfinite(p.gravity_mps2) && p.gravity_mps2 >= kMinGravityMps2 && p.gravity_mps2 <= kMaxGravityMps2))
    return bad_param("gravity_mps2", p.gravity_mps2, "[0.01, 1000] m/s^2");
  if (!p.band.valid())
    return "band: [" + std::to_string(p.band.min_cycles) + ", " + std::to_string(p.band.max_cycles) +
           ") cycles per patch: must be radii in [0, " + std::to_string(WaveBand::kMaxCycles) +
           "], the upper one 0 (none) or above the lower one";
  return {};
}

}  // namespace ocean::model
