// Cascade: one of several lattices that realize a scene's spectrum together, so that the sea they
// sum to repeats no sooner than the largest of them. Each is the scene's patch times patch_scale,
// sampled grid x grid, keeping the waves of its band (cycles per its own patch) and drawing its own
// Gaussians. model/cascade_scene.hpp derives a cascade's scene from these numbers, for the sim and
// the codec alike.
#pragma once

#include "common/wave_band.hpp"

#include <cstdint>

namespace ocean {

struct Cascade {
  int patch_scale = 1;  // the cascade's patch is the scene's times this, in [1, 64]
  int grid = 256;       // samples per side, a power of two in [16, 2048]
  WaveBand band;        // in cycles per the cascade's own patch
  bool operator==(const Cascade&) const = default;
};

// The seed cascade `index` draws with. Cascade 0 keeps the scene's, so a one-cascade stream is the
// scene itself; the others must draw afresh: a lattice that shared the Gaussians of another would
// show a scaled copy of its pattern.
constexpr std::uint64_t cascade_seed(std::uint64_t scene_seed, int index) {
  return scene_seed ^ (0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(index));
}

// Empty if usable, else what is wrong with it.
inline const char* cascade_problem(const Cascade& c) {
  if (c.patch_scale < 1 || c.patch_scale > 64) return "patch_scale must be in [1, 64]";
  if (c.grid < 16 || c.grid > 2048 || (c.grid & (c.grid - 1)) != 0) return "grid must be a power of two in [16, 2048]";
  if (!c.band.valid()) return "band radii must be in [0, 4096], the upper one 0 (none) or above the lower one";
  return "";
}

}  // namespace ocean
