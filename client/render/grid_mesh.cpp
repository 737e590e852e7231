#include "client/render/grid_mesh.hpp"

#include <array>

namespace ocean::render {

std::vector<float> make_grid_positions(int n, float patch_x_m, float patch_z_m) {
  std::vector<float> xz;
  xz.reserve(static_cast<std::size_t>(n + 1) * (n + 1) * 2);
  const float dx = patch_x_m / static_cast<float>(n);
  const float dz = patch_z_m / static_cast<float>(n);
  for (int row = 0; row <= n; ++row) {
    for (int col = 0; col <= n; ++col) {
      // The far edge is written as the patch size itself so adjacent tiles meet bit-exactly.
      xz.push_back(col == n ? patch_x_m : static_cast<float>(col) * dx);
      xz.push_back(row == n ? patch_z_m : static_cast<float>(row) * dz);
    }
  }
  return xz;
}

std::vector<std::uint32_t> make_grid_indices(int n, int level, unsigned coarser_edges, GridRegion region) {
  const int s = 1 << level;
  const int cells = region.cells > 0 ? region.cells : n;
  const int c0 = region.col0, r0 = region.row0, c1 = c0 + cells, r1 = r0 + cells;
  const auto collapse = [&](int col, int row) {
    // Odd multiples of the stride along a stitched edge move onto the previous even vertex.
    if ((coarser_edges & kEdgeMinZ) && row == r0 && (col / s) % 2 == 1) col -= s;
    if ((coarser_edges & kEdgeMaxZ) && row == r1 && (col / s) % 2 == 1) col -= s;
    if ((coarser_edges & kEdgeMinX) && col == c0 && (row / s) % 2 == 1) row -= s;
    if ((coarser_edges & kEdgeMaxX) && col == c1 && (row / s) % 2 == 1) row -= s;
    return static_cast<std::uint32_t>(row * (n + 1) + col);
  };
  std::vector<std::uint32_t> indices;
  indices.reserve(static_cast<std::size_t>(cells / s) * (cells / s) * 6);
  const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) return;
    indices.insert(indices.end(), {a, b, c});
  };
  for (int row = r0; row < r1; row += s) {
    for (int col = c0; col < c1; col += s) {
      const std::uint32_t v00 = collapse(col, row), v10 = collapse(col + s, row);
      const std::uint32_t v01 = collapse(col, row + s), v11 = collapse(col + s, row + s);
      // With +z toward the viewer and +x right, (v00, v01, v11) winds counter-clockwise from +y.
      emit(v00, v01, v11);
      emit(v00, v11, v10);
    }
  }
  return indices;
}

}  // namespace ocean::render
