// The sim's SceneParams of a codec scene: the codec may not depend on the sim, so its tests that
// compare the two convert here.
#pragma once

#include "ocean.hpp"
#include "scene_model_params.hpp"

#include <limits>

namespace ocean::codec::test {

inline ocean::sim::SceneParams to_sim(const SceneModelParams& s) {
  ocean::sim::SceneParams p;
  p.size_x = s.size_x;
  p.size_z = s.size_z;
  p.patch_x_m = s.patch_x_m;
  p.patch_z_m = s.patch_z_m;
  p.spectrum = static_cast<ocean::sim::SpectrumKind>(s.spectrum);
  p.spreading = static_cast<ocean::sim::SpreadingKind>(s.spreading);
  p.wind_speed_mps = s.wind_speed_mps;
  p.wind_dir_deg = s.wind_dir_deg;
  p.fetch_m = s.fetch_m;
  p.amplitude = s.amplitude;
  p.depth_m = s.depth_m == 0.0 ? std::numeric_limits<double>::infinity() : s.depth_m;
  p.small_wave_m = s.small_wave_m;
  p.gravity_mps2 = s.gravity_mps2;
  p.seed = s.seed;
  p.choppiness = s.choppiness;
  p.band = s.band;
  return p;
}

}  // namespace ocean::codec::test
