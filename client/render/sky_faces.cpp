#include "client/render/sky_faces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "client/render/cube_face.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC  // private copy: no clash with another library that embeds stb_image
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace ocean::render {

bool load_sky_faces(const std::string& dir, SkyFaces& out, std::string& error) {
  SkyFaces faces;
  for (int f = 0; f < 6; ++f) {
    const std::string path = dir + "/" + std::string(kCubeFaceNames[f]) + ".png";
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!pixels) {
      error = "cannot read sky face " + path + ": " + stbi_failure_reason();
      return false;
    }
    const bool square = w == h && w > 0;
    const bool same = f == 0 || w == faces.size;
    if (square && same) {
      faces.size = w;
      faces.rgba[f].assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
    }
    stbi_image_free(pixels);
    if (!square || !same) {
      error = "sky face " + path + " is " + std::to_string(w) + "x" + std::to_string(h) +
              "; every face must be square and the same size as px.png";
      return false;
    }
  }
  out = std::move(faces);
  return true;
}

std::vector<std::string> default_sky_dirs() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("OCEAN_SKY_DIR"); env && *env) dirs.emplace_back(env);
#ifdef OCEAN_SKY_BUILD_DIR
  dirs.emplace_back(OCEAN_SKY_BUILD_DIR);
#endif
#ifdef OCEAN_SKY_INSTALL_DIR
  dirs.emplace_back(OCEAN_SKY_INSTALL_DIR);
#endif
  return dirs;
}

bool load_sky(const char* dir, SkyFaces& out, std::string& error) {
  const std::vector<std::string> dirs = dir ? std::vector<std::string>{dir} : default_sky_dirs();
  std::string tried;
  for (const std::string& d : dirs) {
    std::string why;
    if (load_sky_faces(d, out, why)) return true;
    tried += "\n  " + why;
  }
  error = "no sky cube map found (build the ocean_sky_assets target, or give ocean-viewer --sky, "
          "RendererDesc::sky_dir or $OCEAN_SKY_DIR a folder holding px.png .. nz.png, as ocean-skygen "
          "paints them); tried:" + (tried.empty() ? std::string(" nothing") : tried);
  return false;
}

glm::vec3 estimate_sun_direction(const SkyFaces& faces) {
  if (faces.size <= 0) return {0.0f, 1.0f, 0.0f};
  const int n = faces.size;
  const auto luminance = [&](int f, std::size_t i) {
    const std::uint8_t* p = &faces.rgba[f][i * 4];
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  };
  float peak = 0.0f;
  for (int f = 0; f < 6; ++f)
    for (std::size_t i = 0; i < static_cast<std::size_t>(n) * n; ++i) peak = std::max(peak, luminance(f, i));
  glm::vec3 sum{0.0f};
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        if (luminance(f, static_cast<std::size_t>(y) * n + x) < 0.98f * peak) continue;
        sum += cube_face_direction(f, (x + 0.5f) / n, (y + 0.5f) / n);
      }
    }
  }
  return glm::length(sum) > 0.0f ? glm::normalize(sum) : glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::vec3 sample_sky(const SkyFaces& faces, const glm::vec3& direction) {
  if (faces.size <= 0) return glm::vec3(0.0f);
  const CubeTexel t = cube_face_texel(direction);
  const int n = faces.size;
  const int x = std::clamp(static_cast<int>(t.s * n), 0, n - 1);
  const int y = std::clamp(static_cast<int>(t.t * n), 0, n - 1);
  const std::uint8_t* p = &faces.rgba[t.face][(static_cast<std::size_t>(y) * n + x) * 4];
  return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

std::array<glm::vec3, kHorizonRingSize> horizon_ring(const SkyFaces& faces, float elevation_rad) {
  std::array<glm::vec3, kHorizonRingSize> ring{};
  // Average a few azimuths per entry so a cloud edge does not dominate one entry.
  constexpr int kTaps = 8;
  for (int i = 0; i < kHorizonRingSize; ++i) {
    glm::vec3 sum{0.0f};
    for (int k = 0; k < kTaps; ++k) {
      const float a = 6.2831853f * ((i + (k + 0.5f) / kTaps - 0.5f) / kHorizonRingSize - 0.5f);
      sum += sample_sky(faces, {std::cos(a), std::sin(elevation_rad), std::sin(a)});
    }
    ring[i] = sum / float(kTaps);
  }
  return ring;
}

}  // namespace ocean::render
