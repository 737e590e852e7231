// Reading the bound framebuffer back to memory for screenshots and tests.
#pragma once

#include <cstdint>
#include <vector>

namespace ocean::render {

// RGBA8 pixels of the bound framebuffer's (0, 0, width, height) rectangle, top row first
// (GL returns bottom row first; image files and tests expect the opposite).
std::vector<std::uint8_t> read_framebuffer_rgba(int width, int height);

}  // namespace ocean::render
