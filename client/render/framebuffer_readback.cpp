#include "client/render/framebuffer_readback.hpp"

#include <algorithm>

#include <GLES2/gl2.h>

namespace ocean::render {

std::vector<std::uint8_t> read_framebuffer_rgba(int width, int height) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> bottom_up(row * height), top_down(row * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  for (int y = 0; y < height; ++y)
    std::copy_n(&bottom_up[(height - 1 - y) * row], row, &top_down[y * row]);
  return top_down;
}

}  // namespace ocean::render
