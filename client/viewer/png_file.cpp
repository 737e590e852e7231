#include "client/viewer/png_file.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // private copy: no clash with another library that embeds it
#include <stb_image_write.h>

namespace ocean::viewer {

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba, std::string& error) {
  if (rgba.size() != static_cast<std::size_t>(width) * height * 4) {
    error = "write_png: " + std::to_string(rgba.size()) + " bytes do not hold " + std::to_string(width) + "x" +
            std::to_string(height) + " RGBA pixels";
    return false;
  }
  if (!stbi_write_png(path.c_str(), width, height, 4, rgba.data(), width * 4)) {
    error = "cannot write PNG " + path + " (folder missing or not writable?)";
    return false;
  }
  return true;
}

}  // namespace ocean::viewer
