// ocean-skygen: paints the six sky cube-map faces (px.png .. nz.png) into a folder at build time,
// so the project ships no binary images and the sky can be re-generated with other parameters.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // private copy: no clash with another library that embeds it
#include <stb_image_write.h>

#include "assets/skygen/sky_model.hpp"
#include "client/render/cube_face.hpp"

int main(int argc, char** argv) {
  std::string out_dir;
  int size = 256;
  float sun_azimuth_deg = 20.0f, sun_elevation_deg = 12.0f, cloud_cover = 0.45f;
  CLI::App app{"Generate the procedural sky cube map as six PNG faces"};
  app.add_option("--out", out_dir, "output folder (created if missing)")->required();
  app.add_option("--size", size, "face size in pixels")->check(CLI::Range(16, 4096));
  app.add_option("--sun-azimuth-deg", sun_azimuth_deg, "sun azimuth, degrees clockwise from -z toward +x");
  app.add_option("--sun-elevation-deg", sun_elevation_deg, "sun elevation above the horizon, degrees")
      ->check(CLI::Range(-10.0f, 90.0f));
  app.add_option("--cloud-cover", cloud_cover, "0 clear .. 1 overcast")->check(CLI::Range(0.0f, 1.0f));
  CLI11_PARSE(app, argc, argv);

  ocean::assets::SkyModel sky =
      ocean::assets::sky_for_sun(sun_azimuth_deg * 3.14159265f / 180.0f, sun_elevation_deg * 3.14159265f / 180.0f);
  sky.cloud_cover = cloud_cover;

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "ocean-skygen: cannot create --out folder %s: %s\n", out_dir.c_str(), ec.message().c_str());
    return 1;
  }
  std::vector<unsigned char> rgb(static_cast<std::size_t>(size) * size * 3);
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::vec3 dir = ocean::render::cube_face_direction(face, (x + 0.5f) / size, (y + 0.5f) / size);
        const glm::vec3 c = ocean::assets::sky_colour(sky, dir);
        unsigned char* p = &rgb[(static_cast<std::size_t>(y) * size + x) * 3];
        for (int k = 0; k < 3; ++k) p[k] = static_cast<unsigned char>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
      }
    }
    const std::string path = out_dir + "/" + std::string(ocean::render::kCubeFaceNames[face]) + ".png";
    if (!stbi_write_png(path.c_str(), size, size, 3, rgb.data(), size * 3)) {
      std::fprintf(stderr, "ocean-skygen: cannot write %s\n", path.c_str());
      return 1;
    }
  }
  return 0;
}
