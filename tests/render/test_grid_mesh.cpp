// The patch mesh: positions that meet bit-exactly at tile edges, and LOD index lists that cover the
// patch (or one chunk of it) exactly once and stitch to a coarser neighbour without T-junctions.
#include <set>

#include <catch2/catch.hpp>

#include "client/render/grid_mesh.hpp"
#include "client/render/lod.hpp"

using namespace ocean::render;

namespace {

struct Vertex {
  double x, z;
};

Vertex vertex(const std::vector<float>& xz, std::uint32_t i) { return {xz[2 * i], xz[2 * i + 1]}; }

// Twice the signed area seen from +y (positive = counter-clockwise looking down the y axis).
double signed_area2(Vertex a, Vertex b, Vertex c) { return (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z); }

}  // namespace

TEST_CASE("grid positions span the patch and end exactly on its size") {
  const int n = 8;
  const auto xz = make_grid_positions(n, 100.0f, 60.0f);
  REQUIRE(xz.size() == 2u * (n + 1) * (n + 1));
  CHECK(xz[0] == 0.0f);
  CHECK(xz[1] == 0.0f);
  CHECK(xz[2 * n] == 100.0f);                           // last column of row 0
  CHECK(xz[2 * ((n + 1) * (n + 1) - 1) + 1] == 60.0f);  // last row
  CHECK(xz[2 * 1] == Approx(12.5f));
}

TEST_CASE("every LOD level and stitch mask covers its region once, counter-clockwise") {
  const int n = 64;
  const float size = 128.0f, cell = size / n;
  const auto xz = make_grid_positions(n, size, size);
  const GridRegion regions[] = {{}, {0, 0, 32}, {32, 0, 32}, {0, 32, 32}, {32, 32, 32}};
  for (const GridRegion& region : regions) {
    const int cells = region.cells > 0 ? region.cells : n;
    const int levels = supported_lod_levels(cells, 5);
    REQUIRE(levels == 5);
    for (int level = 0; level <= levels; ++level) {
      for (unsigned mask = 0; mask < kEdgeMaskCount; ++mask) {
        if (level == levels && mask != 0) continue;  // the coarsest level has no coarser neighbour
        const auto idx = make_grid_indices(n, level, mask, region);
        REQUIRE(idx.size() % 3 == 0);
        double area2 = 0.0;
        for (std::size_t t = 0; t < idx.size(); t += 3) {
          const Vertex a = vertex(xz, idx[t]), b = vertex(xz, idx[t + 1]), c = vertex(xz, idx[t + 2]);
          REQUIRE(signed_area2(a, b, c) > 0.0);  // no degenerate and no folded-over triangles
          area2 += signed_area2(a, b, c);
          for (const Vertex& v : {a, b, c}) {  // inside the region
            REQUIRE(v.x >= region.col0 * cell);
            REQUIRE(v.x <= (region.col0 + cells) * cell);
            REQUIRE(v.z >= region.row0 * cell);
            REQUIRE(v.z <= (region.row0 + cells) * cell);
          }
        }
        INFO("region " << region.col0 << "," << region.row0 << " level " << level << " mask " << mask);
        CHECK(area2 / 2.0 == Approx(double(cells) * cell * cells * cell).epsilon(1e-9));
        if (mask == 0) CHECK(idx.size() == std::size_t(cells >> level) * (cells >> level) * 6);
      }
    }
  }
}

TEST_CASE("stitched edges use only the coarser neighbour's vertices") {
  const int n = 32;
  const GridRegion regions[] = {{}, {16, 0, 16}, {0, 16, 16}};
  for (const GridRegion& region : regions) {
    const int cells = region.cells > 0 ? region.cells : n;
    const int c0 = region.col0, r0 = region.row0, c1 = c0 + cells, r1 = r0 + cells;
    for (int level = 0; level < supported_lod_levels(cells, 9); ++level) {
      const int coarse = 2 << level;  // the neighbour's stride
      for (unsigned mask = 1; mask < kEdgeMaskCount; ++mask) {
        const auto idx = make_grid_indices(n, level, mask, region);
        std::set<int> on_edge[4];  // positions along each region edge that triangles touch
        for (std::uint32_t i : idx) {
          const int row = int(i) / (n + 1), col = int(i) % (n + 1);
          if (row == r0) on_edge[0].insert(col - c0);
          if (col == c1) on_edge[1].insert(row - r0);
          if (row == r1) on_edge[2].insert(col - c0);
          if (col == c0) on_edge[3].insert(row - r0);
        }
        const unsigned bits[4] = {kEdgeMinZ, kEdgeMaxX, kEdgeMaxZ, kEdgeMinX};
        for (int e = 0; e < 4; ++e) {
          const int expected_step = (mask & bits[e]) ? coarse : (1 << level);
          INFO("region " << c0 << "," << r0 << " level " << level << " mask " << mask << " edge " << e);
          REQUIRE(on_edge[e].size() == std::size_t(cells / expected_step + 1));
          for (int p : on_edge[e]) CHECK(p % expected_step == 0);
        }
      }
    }
  }
}
