// SceneModelParams: the part of a scene that shapes the heights, as the codec's scene model sees
// it. It mirrors the sim's SceneParams field for field because the codec may not depend on the sim:
// clients never link it. Choppiness moves samples but not heights: only the choppy channels use it.
#pragma once

#include "common/wave_band.hpp"

#include <cstdint>
#include <string>

namespace ocean::codec {

enum class ModelSpectrum : std::uint8_t { phillips = 0, jonswap = 1 };
enum class ModelSpreading : std::uint8_t { cos2s = 0, donelan_banner = 1, hasselmann = 2 };

// depth_m 0 = deep water (the sim's infinity); small_wave_m 0 = half the scene's coarser grid spacing.
struct SceneModelParams {
  int size_x = 256, size_z = 256;
  double patch_x_m = 256.0, patch_z_m = 256.0;
  ModelSpectrum spectrum = ModelSpectrum::phillips;
  ModelSpreading spreading = ModelSpreading::donelan_banner;
  double wind_speed_mps = 10.0, wind_dir_deg = 0.0, fetch_m = 100000.0, amplitude = 1.0;
  double depth_m = 0.0, small_wave_m = 0.0, gravity_mps2 = 9.81;
  std::uint64_t seed = 1;
  // Scales the choppy channels (codec version 3), not the heights: scene models ignore it.
  double choppiness = 0.0;
  // The waves this realization keeps, as the sim's SceneParams::band: a cascade's (cascade_model.hpp).
  WaveBand band;
  bool operator==(const SceneModelParams&) const = default;
};

// Empty if usable (the sim's ranges), else a message naming the first bad field and its range.
std::string validate(const SceneModelParams& scene);

}  // namespace ocean::codec
