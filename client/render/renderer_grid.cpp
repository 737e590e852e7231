// The renderer's grid: the tile's vertices and its index table per region, LOD level and edge
// mask, and the far blocks - built once per grid size (set_grid), released with it.
#include "client/render/renderer.hpp"

#include <algorithm>
#include <cmath>

#include "client/render/gl_program.hpp"
#include "client/render/grid_mesh.hpp"
#include "client/render/lod.hpp"
#include "client/render/patch_buffers.hpp"

namespace ocean::render {

void Renderer::release_grid() {
  tile_.destroy();
  far_.destroy();
  index_ranges_.clear();
  n_ = 0;
  has_frame_ = false;
}

bool Renderer::set_grid(int n, float patch_x_m, float patch_z_m) {
  if (!ready_) return fail("Renderer::set_grid called before a successful init");
  if (n < 2 || n > 1024) return fail("set_grid: n = " + std::to_string(n) + " samples per side, allowed 2..1024");
  if (!(patch_x_m > 0.0f) || !(patch_z_m > 0.0f))
    return fail("set_grid: patch size must be > 0 metres, got " + std::to_string(patch_x_m) + " x " + std::to_string(patch_z_m));
  const std::size_t vertices = static_cast<std::size_t>(n + 1) * (n + 1);
  const bool wide = vertices > 65535;
  if (wide && !has_extension("GL_OES_element_index_uint"))
    return fail("set_grid: n = " + std::to_string(n) + " needs 32-bit indices ((n+1)^2 > 65535) but the GL lacks "
                "GL_OES_element_index_uint; use a grid of at most 254 samples per side");
  release_grid();
  n_ = n;
  patch_x_ = patch_x_m;
  patch_z_ = patch_z_m;
  // Chunks must hold whole cells at every level; fall back to whole tiles when they cannot.
  chunks_per_side_ = (n % desc_.chunks_per_side == 0 && n / desc_.chunks_per_side >= 8) ? desc_.chunks_per_side : 1;
  const int chunk_cells = n / chunks_per_side_;
  lod_levels_ = supported_lod_levels(chunk_cells, desc_.max_lod_level);
  index_type_ = wide ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT;

  tile_.create();
  upload_static(tile_.positions, make_grid_positions(n, patch_x_m, patch_z_m));

  build_tile_indices(n, chunk_cells, wide);
  build_far_blocks(n, patch_x_m, patch_z_m, wide);
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) return fail("GL error " + std::to_string(e) + " while uploading the grid");
  return true;
}

// One index buffer for every (region, LOD level, coarser-edge mask): region 0 is the whole tile,
// then each chunk; ranges are found by index_ranges_.
void Renderer::build_tile_indices(int n, int chunk_cells, bool wide) {
  std::vector<std::uint32_t> all;
  const int regions = 1 + (chunks_per_side_ > 1 ? chunks_per_side_ * chunks_per_side_ : 0);
  index_ranges_.assign(static_cast<std::size_t>(regions) * (lod_levels_ + 1) * kEdgeMaskCount, {});
  const std::size_t element = wide ? 4 : 2;
  for (int region = 0; region < regions; ++region) {
    GridRegion r;  // region 0: the whole tile
    if (region > 0) r = {((region - 1) % chunks_per_side_) * chunk_cells, ((region - 1) / chunks_per_side_) * chunk_cells, chunk_cells};
    for (int level = 0; level <= lod_levels_; ++level) {
      for (unsigned mask = 0; mask < kEdgeMaskCount; ++mask) {
        // The coarsest level never has a coarser neighbour.
        const std::vector<std::uint32_t> part = make_grid_indices(n, level, level < lod_levels_ ? mask : 0u, r);
        index_ranges_[(region * (lod_levels_ + 1) + level) * kEdgeMaskCount + mask] = {all.size() * element,
                                                                                      static_cast<GLsizei>(part.size())};
        all.insert(all.end(), part.begin(), part.end());
      }
    }
  }
  upload_indices(tile_.indices, all, wide);
}

// Far blocks: a plain grid over far_span_^2 patches at the coarsest stride (never stitched).
void Renderer::build_far_blocks(int n, float patch_x_m, float patch_z_m, bool wide) {
  const float patch = std::max(patch_x_m, patch_z_m);
  far_span_ = desc_.far_block_tiles > 0 ? desc_.far_block_tiles
                                        : std::clamp(static_cast<int>(std::lround(desc_.view_distance_m / (5.0f * patch))), 1, 16);
  if (far_span_ > 1) {
    const int far_cells = far_span_ * (n >> lod_levels_);
    const bool far_wide = static_cast<std::size_t>(far_cells + 1) * (far_cells + 1) > 65535;
    if (far_wide && !wide) {
      far_span_ = 1;  // keep 16-bit indices; the far field is then drawn tile by tile
    } else {
      far_.create();
      upload_static(far_.positions, make_grid_positions(far_cells, far_span_ * patch_x_m, far_span_ * patch_z_m));
      const std::vector<std::uint32_t> far_indices = make_grid_indices(far_cells, 0, 0u);
      upload_indices(far_.indices, far_indices, far_wide);
      far_index_count_ = static_cast<GLsizei>(far_indices.size());
      far_index_type_ = far_wide ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT;
    }
  }
}

}  // namespace ocean::render
