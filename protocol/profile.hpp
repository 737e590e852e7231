// Stream profiles: the one place that says what each named stream carries and how finely.
// The server offers a subset; the codec, the protocol checks and the clients all read this table.
#pragma once

#include "common/cascade.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace ocean {

struct Profile {
  std::uint8_t id;          // wire id, stable forever once released
  std::string_view name;    // what users type: --profile mobile
  std::uint16_t grid;       // the stream is grid x grid samples, band-limited from the sim
  std::uint16_t rate_hz;    // frames per second
  bool normals;             // slopes (dh/dx, dh/dz) are delivered, error-bounded by slope_step / 2
  bool choppy;              // horizontal displacement and Jacobian are delivered
  float height_step_m;      // height quantization step; reconstruction error <= step / 2
  float slope_step;         // slope quantization step (dimensionless)
  float disp_step_m;        // displacement quantization step (choppy profiles)
  // The stream's lattices (codec version 5), the first of `grid` samples; empty: one lattice of
  // the scene's patch with every wave.
  std::span<const Cascade> cascades = {};
  // Samples per side of the wake lattice (CODEC.md 7.9) when the server runs vessels.
  std::uint16_t wake_grid = 64;
};

// Desktop: a 256 m tile of the waves under 32 m and a 2048 m cascade of the longer ones, so the
// sea repeats every 2 km instead of every tile (issue 17: from 400 m up, the picture's correlation
// at the tile's period falls from 0.80 to 0.27, test_render_gl), for a quarter more decoding.
inline constexpr Cascade kDesktopCascades[] = {{1, 256, {8, 0}}, {8, 128, {0, 64}}};

inline constexpr Profile kProfiles[] = {
    // id  name              grid rate normals choppy  h-step  slope-step   disp-step
    {1, "mobile",          64,  30,  true,   false,  0.01f,  1.0f / 256,  0.01f},
    {2, "desktop",         256, 30,  true,   false,  0.01f,  1.0f / 256,  0.01f, kDesktopCascades, 128},
    {3, "desktop-choppy",  256, 30,  true,   true,   0.01f,  1.0f / 256,  0.01f, kDesktopCascades, 128},
    {4, "lite",            32,  15,  true,   false,  0.02f,  1.0f / 128,  0.02f, {}, 32},
    // Choppy channels are predicted from the heights like the slopes (codec version 3), so a
    // phone's storm costs what its calm sea costs on the wire; only the decode doubles.
    {5, "mobile-choppy",   64,  30,  true,   true,   0.01f,  1.0f / 256,  0.01f},
};

inline std::span<const Profile> all_profiles() { return kProfiles; }

inline const Profile* find_profile(std::string_view name) {
  for (const Profile& p : kProfiles)
    if (p.name == name) return &p;
  return nullptr;
}

inline const Profile* find_profile(std::uint8_t id) {
  for (const Profile& p : kProfiles)
    if (p.id == id) return &p;
  return nullptr;
}

}  // namespace ocean
