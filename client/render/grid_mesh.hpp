// The static patch mesh: (n+1) x (n+1) vertex positions (the last row/column repeats the first
// sample of the periodic field, so neighbouring tiles share edge heights exactly) and the triangle
// lists for each LOD level, with edges stitched to a coarser neighbour.
#pragma once

#include <cstdint>
#include <vector>

namespace ocean::render {

// Bit flags naming tile edges; vertex (col, row) sits at x = col * dx, z = row * dz.
enum TileEdge : unsigned {
  kEdgeMinZ = 1u,  // row 0
  kEdgeMaxX = 2u,  // col n
  kEdgeMaxZ = 4u,  // row n
  kEdgeMinX = 8u,  // col 0
};
inline constexpr unsigned kEdgeMaskCount = 16;

// Interleaved (x, z) metres for (n+1)^2 vertices, row-major (row = z index).
std::vector<float> make_grid_positions(int n, float patch_x_m, float patch_z_m);

// A square block of cells of the (n+1)^2 vertex grid: the whole patch, or one chunk of it.
struct GridRegion {
  int col0 = 0, row0 = 0;  // first cell
  int cells = 0;           // cells per side; 0 = the whole patch (n)
};

// Triangles (counter-clockwise seen from +y) covering the region at vertex stride 2^level.
// Along each region edge in coarser_edges the odd vertices of this stride are collapsed onto
// their even neighbour, so the edge matches a neighbour one level coarser with no T-junction
// crack; triangles that collapse to zero area are dropped. Requires cells % 2^(level+1) == 0 on
// stitched edges (see supported_lod_levels) and col0, row0 multiples of 2^(level+1).
std::vector<std::uint32_t> make_grid_indices(int n, int level, unsigned coarser_edges, GridRegion region = {});

}  // namespace ocean::render
