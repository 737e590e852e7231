// The six sky cube-map images in memory, where to find them on disk, and what the renderer
// reads from them (the sun direction, so highlights line up with the painted sun).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::render {

struct SkyFaces {
  int size = 0;                                    // every face is size x size
  std::array<std::vector<std::uint8_t>, 6> rgba;  // GL face order (kCubeFaceNames)
};

// Loads <dir>/px.png ... nz.png. On failure returns false and says which file and why.
bool load_sky_faces(const std::string& dir, SkyFaces& out, std::string& error);

// The folders searched when no folder is given: $OCEAN_SKY_DIR, the build tree, the install tree.
std::vector<std::string> default_sky_dirs();

// Loads from dir, or (dir null) from the first of default_sky_dirs() that holds a sky; on
// failure the error lists every folder tried and how to produce the faces.
bool load_sky(const char* dir, SkyFaces& out, std::string& error);

// Direction of the brightest spot of the sky (the sun disc): mean direction of the texels
// within 2% of the peak luminance. Returns (0, 1, 0) for an empty set of faces.
glm::vec3 estimate_sun_direction(const SkyFaces& faces);

// Colour in [0, 1] of the texel nearest to a direction.
glm::vec3 sample_sky(const SkyFaces& faces, const glm::vec3& direction);

// Sky colours just above the horizon at kHorizonRingSize azimuths; entry i looks along
// (cos a, 0, sin a) with a = 2 pi (i / size - 0.5). The renderer fades distant water into these.
inline constexpr int kHorizonRingSize = 16;
std::array<glm::vec3, kHorizonRingSize> horizon_ring(const SkyFaces& faces, float elevation_rad);

}  // namespace ocean::render
