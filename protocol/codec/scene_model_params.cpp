// The sim's ranges: a scene the sim accepts is a scene the model accepts, and the spectrum's
// arithmetic stays finite inside them.
#include "scene_model_params.hpp"

#include <cmath>
#include <sstream>

namespace ocean::codec {
namespace {

bool power_of_two_in(int n, int lo, int hi) { return n >= lo && n <= hi && (n & (n - 1)) == 0; }
bool in_range(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace

std::string validate(const SceneModelParams& p) {
  std::ostringstream m;
  if (!power_of_two_in(p.size_x, 16, 2048))
    m << "size_x = " << p.size_x << ": must be a power of two in [16, 2048]";
  else if (!power_of_two_in(p.size_z, 16, 2048))
    m << "size_z = " << p.size_z << ": must be a power of two in [16, 2048]";
  else if (!in_range(p.patch_x_m, 0.01, 1e6))
    m << "patch_x_m = " << p.patch_x_m << ": must be in [0.01, 1e6] metres";
  else if (!in_range(p.patch_z_m, 0.01, 1e6))
    m << "patch_z_m = " << p.patch_z_m << ": must be in [0.01, 1e6] metres";
  else if (p.spectrum != ModelSpectrum::phillips && p.spectrum != ModelSpectrum::jonswap)
    m << "spectrum = " << static_cast<int>(p.spectrum) << ": must be phillips (0) or jonswap (1)";
  else if (p.spreading != ModelSpreading::cos2s && p.spreading != ModelSpreading::donelan_banner &&
           p.spreading != ModelSpreading::hasselmann)
    m << "spreading = " << static_cast<int>(p.spreading) << ": must be cos2s (0), donelan_banner (1) or hasselmann (2)";
  else if (!in_range(p.wind_speed_mps, 0.0, 100.0))
    m << "wind_speed_mps = " << p.wind_speed_mps << ": must be in [0, 100]";
  else if (!in_range(p.wind_dir_deg, -1e6, 1e6))
    m << "wind_dir_deg = " << p.wind_dir_deg << ": must be in [-1e6, 1e6]";
  else if (!in_range(p.fetch_m, 1.0, 1e8))
    m << "fetch_m = " << p.fetch_m << ": must be in [1, 1e8]";
  else if (!in_range(p.amplitude, 0.0, 1e6))
    m << "amplitude = " << p.amplitude << ": must be in [0, 1e6]";
  else if (!(std::isfinite(p.depth_m) && p.depth_m >= 0.0))
    m << "depth_m = " << p.depth_m << ": must be finite and >= 0 (0 = deep water)";
  else if (!in_range(p.small_wave_m, 0.0, 1e6))
    m << "small_wave_m = " << p.small_wave_m << ": must be in [0, 1e6] (0 = half the grid spacing)";
  else if (!in_range(p.gravity_mps2, 0.01, 1000.0))
    m << "gravity_mps2 = " << p.gravity_mps2 << ": must be in [0.01, 1000]";
  else if (!in_range(p.choppiness, 0.0, 100.0))
    m << "choppiness = " << p.choppiness << ": must be in [0, 100]";
  else if (!p.band.valid())
    m << "band = [" << p.band.min_cycles << ", " << p.band.max_cycles << ") cycles per patch: must be radii in [0, "
      << WaveBand::kMaxCycles << "], the upper one 0 (none) or above the lower one";
  return m.str();
}

}  // namespace ocean::codec
