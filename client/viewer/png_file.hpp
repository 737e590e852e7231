// Writing RGBA pixels (top row first) to a PNG file, for --screenshot.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ocean::viewer {

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba, std::string& error);

}  // namespace ocean::viewer
