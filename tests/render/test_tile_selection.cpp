// Tile selection: range, frustum culling with the displacement margin, ordering, and LOD balance.
#include <cmath>
#include <map>

#include <catch2/catch.hpp>

#include "client/render/camera.hpp"
#include "client/render/grid_mesh.hpp"
#include "client/render/tile_selection.hpp"

using namespace ocean::render;

namespace {

TileSelectionInput looking_north(float pitch_deg = -10.0f) {
  Camera c;
  c.position = {10.0, 12.0, 20.0};
  c.pitch_rad = pitch_deg * 3.14159265f / 180.0f;
  c.far_m = 4000.0f;
  TileSelectionInput in;
  in.camera_position = c.position;
  in.clip_from_relative = c.clip_from_relative(16.0f / 9.0f);
  in.patch_x_m = in.patch_z_m = 100.0f;
  in.view_distance_m = 1500.0f;
  in.max_height_m = 2.0f;
  in.lod = {60.0f, 5};
  in.chunks_per_side = 2;
  in.far_block_tiles = 4;
  return in;
}

}  // namespace

TEST_CASE("selected tiles are in range, in front of the eye, nearest first") {
  const TileSelectionInput in = looking_north();
  const TileSelection sel = select_tiles(in);
  REQUIRE(sel.draws.size() > 20);
  CHECK(sel.culled > int(sel.draws.size()) / 2);  // a 60 degree view culls most of the disc
  float previous = 0.0f;
  bool has_camera_tile = false;
  for (const TileDraw& t : sel.draws) {
    CHECK(t.distance_m >= previous);
    previous = t.distance_m;
    CHECK(t.distance_m <= std::hypot(in.view_distance_m, 12.0f) + 1e-3f);
    // Looking along -z: no tile lies wholly behind the eye (tile z range above the eye's z).
    CHECK(t.iz * 100.0 < in.camera_position.z + 1.0);
    CHECK(t.offset_relative.x == Approx(t.ix * 100.0 - in.camera_position.x));
    if (t.ix == 0 && t.iz == 0) has_camera_tile = true;
  }
  CHECK(has_camera_tile);
  CHECK(sel.draws.front().level == 0);
  CHECK(sel.draws.back().level == 5);
}

TEST_CASE("neighbouring chunks differ by at most one LOD level and flag the coarser side") {
  const TileSelectionInput in = looking_north();
  const int c = in.chunks_per_side;
  const TileSelection sel = select_tiles(in);
  // Every drawn chunk cell (global chunk coordinates) and the level it is drawn at.
  std::map<std::pair<int, int>, int> level;
  struct Extent {
    int gx0, gz0, size;
  };
  const auto extent = [&](const TileDraw& t) {
    return t.chunk < 0 ? Extent{t.ix * c, t.iz * c, c * t.span} : Extent{t.ix * c + t.chunk % c, t.iz * c + t.chunk / c, 1};
  };
  for (const TileDraw& t : sel.draws) {
    const Extent e = extent(t);
    for (int j = 0; j < e.size; ++j)
      for (int i = 0; i < e.size; ++i) REQUIRE(level.emplace(std::make_pair(e.gx0 + i, e.gz0 + j), t.level).second);
  }
  int stitched = 0, whole = 0, chunks = 0, blocks = 0;
  for (const TileDraw& t : sel.draws) {
    (t.span > 1 ? blocks : t.chunk < 0 ? whole : chunks)++;
    if (t.span > 1) {  // far blocks: aligned, coarsest, never stitched
      CHECK(t.span == in.far_block_tiles);
      CHECK(t.ix % t.span == 0);
      CHECK(t.iz % t.span == 0);
      CHECK(t.level == in.lod.max_level);
      CHECK(t.coarser_edges == 0u);
    }
    const Extent e = extent(t);
    const unsigned bits[4] = {kEdgeMinZ, kEdgeMaxX, kEdgeMaxZ, kEdgeMinX};
    for (int side = 0; side < 4; ++side) {
      for (int k = 0; k < e.size; ++k) {
        // The neighbouring cell just outside this side, k cells along it.
        const int gx = side == 1 ? e.gx0 + e.size : (side == 3 ? e.gx0 - 1 : e.gx0 + k);
        const int gz = side == 0 ? e.gz0 - 1 : (side == 2 ? e.gz0 + e.size : e.gz0 + k);
        const auto it = level.find({gx, gz});
        if (it == level.end()) continue;
        const bool flagged = (t.coarser_edges & bits[side]) != 0;
        INFO("tile " << t.ix << "," << t.iz << " chunk " << t.chunk << " level " << t.level << " side " << side
                     << " neighbour level " << it->second);
        REQUIRE(std::abs(it->second - t.level) <= 1);
        CHECK(flagged == (it->second == t.level + 1));
        stitched += flagged;
      }
    }
  }
  CHECK(stitched > 0);
  CHECK(chunks > 0);        // the tiles near the eye mix levels
  CHECK(whole > 0);
  CHECK(blocks > 0);        // the far field is drawn in blocks of tiles
  TileSelectionInput per_tile = in;
  per_tile.far_block_tiles = 1;
  CHECK(sel.draws.size() + blocks < select_tiles(per_tile).draws.size());
}

TEST_CASE("a larger wave margin keeps tiles near the frustum edge") {
  TileSelectionInput in = looking_north(-30.0f);
  const auto covered_chunks = [&](const TileSelection& sel) {
    int cells = 0;
    for (const TileDraw& t : sel.draws)
      cells += t.chunk < 0 ? t.span * t.span * in.chunks_per_side * in.chunks_per_side : 1;
    return cells;
  };
  const TileSelection tight = select_tiles(in);
  in.max_height_m = 40.0f;
  in.max_displacement_m = 30.0f;
  const TileSelection loose = select_tiles(in);
  CHECK(covered_chunks(loose) > covered_chunks(tight));
  CHECK(loose.culled < tight.culled);
}

TEST_CASE("no tiles without a patch size") {
  TileSelectionInput in = looking_north();
  in.patch_x_m = 0.0f;
  CHECK(select_tiles(in).draws.empty());
}
