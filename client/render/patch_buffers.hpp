// The GL buffers of one drawable grid (a tile, or a far block of tiles): static (x, z) positions
// and triangle indices, and the per-frame attribute streams bound to the ocean shader's slots.
#pragma once

#include <cstdint>
#include <vector>

#include <GLES2/gl2.h>

namespace ocean::render {

// Attribute slots of shaders/ocean.vert.glsl, fixed before linking.
enum OceanAttribute : GLuint { kGrid = 0, kHeight = 1, kSlope = 2, kDisp = 3, kJacobian = 4 };

struct PatchBuffers {
  GLuint positions = 0, indices = 0;                      // static
  GLuint height = 0, slope = 0, displacement = 0, jacobian = 0;  // streamed

  void create();
  void destroy();
  // Enables the attribute arrays; a stream not present becomes a constant (no displacement, J = 1).
  void bind(bool has_displacement, bool has_jacobian) const;
  static void unbind();
};

void upload_static(GLuint buffer, const std::vector<float>& data);
void upload_stream(GLuint buffer, const std::vector<float>& data);
// 16-bit indices unless wide (then GL_OES_element_index_uint is required).
void upload_indices(GLuint buffer, const std::vector<std::uint32_t>& indices, bool wide);

}  // namespace ocean::render
