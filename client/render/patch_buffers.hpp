// The GL buffers of one drawable grid (a tile, or a far block of tiles): static (x, z) positions
// and triangle indices, and the per-frame attribute streams bound to the ocean shader's slots.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include <GLES2/gl2.h>

namespace ocean::render {

// Attribute slots of shaders/ocean.vert.glsl, fixed before linking.
enum OceanAttribute : GLuint { kGrid = 0, kHeight = 1, kSlope = 2, kDisp = 3, kJacobian = 4 };

// The shader's streamed attributes, one row each, in slot order from kHeight: the name the shader
// reads, its floats per vertex, and the constant a vertex reads when a frame lacks the stream.
struct OceanStream {
  OceanAttribute slot;
  const char* name;
  GLint components;
  float absent[2];
};
inline constexpr OceanStream kOceanStreams[] = {
    {kHeight, "a_height", 1, {0.0f, 0.0f}},
    {kSlope, "a_slope", 2, {0.0f, 0.0f}},
    {kDisp, "a_disp", 2, {0.0f, 0.0f}},        // no displacement
    {kJacobian, "a_jacobian", 1, {1.0f, 0.0f}},  // J = 1: no fold, no foam
};
inline constexpr std::size_t kOceanStreamCount = std::size(kOceanStreams);
// Which streams a frame gave, by kOceanStreams' order.
using StreamsPresent = std::array<bool, kOceanStreamCount>;

struct PatchBuffers {
  GLuint positions = 0, indices = 0;            // static
  std::array<GLuint, kOceanStreamCount> streams{};  // by kOceanStreams' order

  GLuint stream(OceanAttribute a) const { return streams[a - kHeight]; }
  void create();
  void destroy();
  // Enables the attribute arrays; a stream not present becomes its row's constant.
  void bind(const StreamsPresent& present) const;
  static void unbind();
};

void upload_static(GLuint buffer, const std::vector<float>& data);
void upload_stream(GLuint buffer, const std::vector<float>& data);
// 16-bit indices unless wide (then GL_OES_element_index_uint is required).
void upload_indices(GLuint buffer, const std::vector<std::uint32_t>& indices, bool wide);

}  // namespace ocean::render
