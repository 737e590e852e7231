// select_tiles in its phases: the window of tiles around the camera and its chunk grid; a level
// per chunk from its distance; balancing neighbours to one level apart; range and frustum
// culling; edge flags towards coarser neighbours; far blocks; then one draw per tile or per chunk.
#include "client/render/tile_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "client/render/frustum.hpp"
#include "client/render/grid_mesh.hpp"

namespace ocean::render {

namespace {

// Distance from a point to the interval [lo, hi] along one axis.
double gap(double p, double lo, double hi) { return p < lo ? lo - p : (p > hi ? p - hi : 0.0); }

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// From the eye to the nearest point of the sea-level rectangle [x0, x0 + width] x [z0, z0 + depth].
float eye_distance_to_rect(const glm::dvec3& eye, double x0, double z0, double width, double depth) {
  const double dx = gap(eye.x, x0, x0 + width), dz = gap(eye.z, z0, z0 + depth);
  return static_cast<float>(std::sqrt(dx * dx + dz * dz + eye.y * eye.y));
}

// The square of tiles around the camera's tile that can hold anything within the view distance.
// Tiles are indexed in the world (ix, iz) and within the window (tx, tz) from its first tile.
struct TileWindow {
  int chunks_per_side = 1;  // per tile side
  double tile_x_m = 0.0, tile_z_m = 0.0;
  double chunk_x_m = 0.0, chunk_z_m = 0.0;
  int camera_ix = 0, camera_iz = 0;  // the tile the eye is above
  int radius_x = 0, radius_z = 0;    // tiles on each side of the camera's tile
  int tiles_x = 0, tiles_z = 0;
  double origin_x_m = 0.0, origin_z_m = 0.0;  // world corner of the first tile

  int first_ix() const { return camera_ix - radius_x; }
  int first_iz() const { return camera_iz - radius_z; }
  bool contains(int tx, int tz) const { return tx >= 0 && tz >= 0 && tx < tiles_x && tz < tiles_z; }
};

TileWindow window_around_camera(const TileSelectionInput& in) {
  TileWindow w;
  w.chunks_per_side = std::max(1, in.chunks_per_side);
  w.tile_x_m = in.patch_x_m;
  w.tile_z_m = in.patch_z_m;
  w.chunk_x_m = w.tile_x_m / w.chunks_per_side;
  w.chunk_z_m = w.tile_z_m / w.chunks_per_side;
  w.camera_ix = static_cast<int>(std::floor(in.camera_position.x / w.tile_x_m));
  w.camera_iz = static_cast<int>(std::floor(in.camera_position.z / w.tile_z_m));
  w.radius_x = static_cast<int>(std::ceil(in.view_distance_m / w.tile_x_m)) + 1;
  w.radius_z = static_cast<int>(std::ceil(in.view_distance_m / w.tile_z_m)) + 1;
  w.tiles_x = 2 * w.radius_x + 1;
  w.tiles_z = 2 * w.radius_z + 1;
  w.origin_x_m = w.first_ix() * w.tile_x_m;
  w.origin_z_m = w.first_iz() * w.tile_z_m;
  return w;
}

struct ChunkState {
  float distance = 0.0f;
  int level = 0;
  bool in_range = false;
  bool visible = false;  // in range and possibly inside the frustum
  unsigned coarser_edges = 0;
};

// Every chunk of the window, row-major over chunk coordinates (gx, gz).
class ChunkGrid {
 public:
  explicit ChunkGrid(const TileWindow& window)
      : per_tile_(window.chunks_per_side),
        width_(window.tiles_x * per_tile_),
        depth_(window.tiles_z * per_tile_),
        chunks_(static_cast<std::size_t>(width_) * depth_) {}

  int width() const { return width_; }
  int depth() const { return depth_; }
  ChunkState& at(int gx, int gz) { return chunks_[static_cast<std::size_t>(gz) * width_ + gx]; }
  const ChunkState& at(int gx, int gz) const { return chunks_[static_cast<std::size_t>(gz) * width_ + gx]; }
  // Chunk (col, row) of window tile (tx, tz).
  const ChunkState& in_tile(int tx, int tz, int col, int row) const { return at(tx * per_tile_ + col, tz * per_tile_ + row); }

 private:
  int per_tile_, width_, depth_;
  std::vector<ChunkState> chunks_;
};

// Chunk-level detail only where it pays (the tile would be at level 0 or 1); further out the
// whole tile shares one level so it stays one draw call.
void assign_levels_by_distance(ChunkGrid& grid, const TileWindow& w, const TileSelectionInput& in) {
  const glm::dvec3 eye = in.camera_position;
  const int per_tile = w.chunks_per_side;
  for (int gz = 0; gz < grid.depth(); ++gz) {
    for (int gx = 0; gx < grid.width(); ++gx) {
      ChunkState& chunk = grid.at(gx, gz);
      chunk.distance = eye_distance_to_rect(eye, w.origin_x_m + gx * w.chunk_x_m, w.origin_z_m + gz * w.chunk_z_m,
                                            w.chunk_x_m, w.chunk_z_m);
      const float tile_distance = eye_distance_to_rect(eye, w.origin_x_m + (gx / per_tile) * w.tile_x_m,
                                                       w.origin_z_m + (gz / per_tile) * w.tile_z_m, w.tile_x_m, w.tile_z_m);
      const int tile_level = lod_level_for_distance(tile_distance, in.lod);
      chunk.level = tile_level <= 1 ? lod_level_for_distance(chunk.distance, in.lod) : tile_level;
    }
  }
}

// Restricted-quadtree style balance: a chunk may be at most one level coarser than any neighbour.
void balance_neighbour_levels(ChunkGrid& grid) {
  for (bool changed = true; changed;) {
    changed = false;
    for (int gz = 0; gz < grid.depth(); ++gz) {
      for (int gx = 0; gx < grid.width(); ++gx) {
        int limit = grid.at(gx, gz).level;
        if (gx > 0) limit = std::min(limit, grid.at(gx - 1, gz).level + 1);
        if (gx + 1 < grid.width()) limit = std::min(limit, grid.at(gx + 1, gz).level + 1);
        if (gz > 0) limit = std::min(limit, grid.at(gx, gz - 1).level + 1);
        if (gz + 1 < grid.depth()) limit = std::min(limit, grid.at(gx, gz + 1).level + 1);
        if (limit < grid.at(gx, gz).level) {
          grid.at(gx, gz).level = limit;
          changed = true;
        }
      }
    }
  }
}

// In range: horizontally within the view distance. Visible: in range and its box, grown by the
// wave height and displacement margins, may be inside the frustum.
void cull_chunks(ChunkGrid& grid, const TileWindow& w, const TileSelectionInput& in) {
  const glm::dvec3 eye = in.camera_position;
  const Frustum frustum = Frustum::from_clip_matrix(in.clip_from_relative);
  const float margin_xz = in.max_displacement_m;
  const float margin_y = in.max_height_m + in.max_displacement_m;
  for (int gz = 0; gz < grid.depth(); ++gz) {
    for (int gx = 0; gx < grid.width(); ++gx) {
      ChunkState& chunk = grid.at(gx, gz);
      const double horizontal = std::sqrt(std::max(0.0, double(chunk.distance) * chunk.distance - eye.y * eye.y));
      chunk.in_range = horizontal <= in.view_distance_m;
      if (!chunk.in_range) continue;
      const float x0 = static_cast<float>(w.origin_x_m + gx * w.chunk_x_m - eye.x);
      const float z0 = static_cast<float>(w.origin_z_m + gz * w.chunk_z_m - eye.z);
      const Aabb box{{x0 - margin_xz, static_cast<float>(-margin_y - eye.y), z0 - margin_xz},
                     {x0 + static_cast<float>(w.chunk_x_m) + margin_xz, static_cast<float>(margin_y - eye.y),
                      z0 + static_cast<float>(w.chunk_z_m) + margin_xz}};
      chunk.visible = frustum.may_see(box);
    }
  }
}

// Flags each side whose neighbour is one level coarser: the edge stitching closes those seams.
void flag_coarser_neighbours(ChunkGrid& grid) {
  for (int gz = 0; gz < grid.depth(); ++gz) {
    for (int gx = 0; gx < grid.width(); ++gx) {
      ChunkState& chunk = grid.at(gx, gz);
      if (gz > 0 && grid.at(gx, gz - 1).level > chunk.level) chunk.coarser_edges |= kEdgeMinZ;
      if (gz + 1 < grid.depth() && grid.at(gx, gz + 1).level > chunk.level) chunk.coarser_edges |= kEdgeMaxZ;
      if (gx > 0 && grid.at(gx - 1, gz).level > chunk.level) chunk.coarser_edges |= kEdgeMinX;
      if (gx + 1 < grid.width() && grid.at(gx + 1, gz).level > chunk.level) chunk.coarser_edges |= kEdgeMaxX;
    }
  }
}

// What a group of chunks drawn together adds up to.
struct ChunkTally {
  bool any_visible = false;
  int culled = 0;  // in range but outside the frustum
  float nearest = std::numeric_limits<float>::max();  // of the visible chunks

  void add(const ChunkState& chunk) {
    any_visible = any_visible || chunk.visible;
    culled += chunk.in_range && !chunk.visible;
    if (chunk.visible) nearest = std::min(nearest, chunk.distance);
  }
};

// Adds the chunks of window tile (tx, tz) to the tally; false if any is finer than max_level.
bool tally_coarsest_tile(const ChunkGrid& grid, int per_tile, int tx, int tz, int max_level, ChunkTally& tally) {
  bool coarsest = true;
  for (int row = 0; row < per_tile; ++row) {
    for (int col = 0; col < per_tile; ++col) {
      const ChunkState& chunk = grid.in_tile(tx, tz, col, row);
      coarsest = coarsest && chunk.level == max_level;
      tally.add(chunk);
    }
  }
  return coarsest;
}

// Far blocks: span x span tiles, aligned to multiples of span, every chunk at the coarsest level
// (tiles outside the window are beyond the view distance, so they count as coarsest too). A block
// never needs stitching: nothing is coarser. Returns which window tiles the blocks cover.
std::vector<char> select_far_blocks(const ChunkGrid& grid, const TileWindow& w, const TileSelectionInput& in,
                                    TileSelection& out) {
  std::vector<char> in_block(static_cast<std::size_t>(w.tiles_x) * w.tiles_z, 0);
  const int span = std::max(1, in.far_block_tiles);
  if (span == 1) return in_block;
  const glm::dvec3 eye = in.camera_position;
  for (int bz = floor_div(w.first_iz(), span); bz <= floor_div(w.camera_iz + w.radius_z, span); ++bz) {
    for (int bx = floor_div(w.first_ix(), span); bx <= floor_div(w.camera_ix + w.radius_x, span); ++bx) {
      ChunkTally tally;
      bool coarsest = true;
      for (int iz = bz * span; iz < (bz + 1) * span && coarsest; ++iz) {
        for (int ix = bx * span; ix < (bx + 1) * span && coarsest; ++ix) {
          const int tx = ix - w.first_ix(), tz = iz - w.first_iz();
          if (w.contains(tx, tz))
            coarsest = tally_coarsest_tile(grid, w.chunks_per_side, tx, tz, in.lod.max_level, tally);
        }
      }
      if (!coarsest || !tally.any_visible) continue;
      for (int iz = bz * span; iz < (bz + 1) * span; ++iz) {
        for (int ix = bx * span; ix < (bx + 1) * span; ++ix) {
          const int tx = ix - w.first_ix(), tz = iz - w.first_iz();
          if (w.contains(tx, tz)) in_block[static_cast<std::size_t>(tz) * w.tiles_x + tx] = 1;
        }
      }
      out.culled += tally.culled;
      const glm::vec2 offset{static_cast<float>(bx * span * w.tile_x_m - eye.x),
                             static_cast<float>(bz * span * w.tile_z_m - eye.z)};
      out.draws.push_back({bx * span, bz * span, -1, span, offset, tally.nearest, in.lod.max_level, 0u});
    }
  }
  return in_block;
}

// The tile's coarser-edge flags when, along each side, all its chunks are flagged alike (so the
// tile can be stitched as one piece); none when they differ.
std::optional<unsigned> uniform_tile_edges(const ChunkGrid& grid, int per_tile, int tx, int tz) {
  const unsigned side_flag[4] = {kEdgeMinZ, kEdgeMaxX, kEdgeMaxZ, kEdgeMinX};
  unsigned mask = 0;
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < per_tile; ++k) {
      const int col = side == 1 ? per_tile - 1 : (side == 3 ? 0 : k);
      const int row = side == 0 ? 0 : (side == 2 ? per_tile - 1 : k);
      const unsigned flag = grid.in_tile(tx, tz, col, row).coarser_edges & side_flag[side];
      if (k > 0 && flag != (mask & side_flag[side])) return std::nullopt;
      mask |= flag;
    }
  }
  return mask;
}

// A tile with any visible chunk is drawn: whole if its chunks agree (same level, each side
// stitched alike), even if some are just outside the view (clipping them costs less than extra
// draw calls); else chunk by chunk, the visible ones only.
void select_tile_draws(const ChunkGrid& grid, const TileWindow& w, const TileSelectionInput& in, int tx, int tz,
                       TileSelection& out) {
  const int per_tile = w.chunks_per_side;
  const int ix = w.first_ix() + tx, iz = w.first_iz() + tz;
  const glm::vec2 offset{static_cast<float>(ix * w.tile_x_m - in.camera_position.x),
                         static_cast<float>(iz * w.tile_z_m - in.camera_position.z)};
  const ChunkState& first = grid.in_tile(tx, tz, 0, 0);
  bool same_level = true;
  ChunkTally tally;
  for (int row = 0; row < per_tile; ++row) {
    for (int col = 0; col < per_tile; ++col) {
      const ChunkState& chunk = grid.in_tile(tx, tz, col, row);
      same_level = same_level && chunk.level == first.level;
      tally.add(chunk);
    }
  }
  if (!tally.any_visible) {
    out.culled += tally.culled;
    return;
  }
  if (const auto edges = same_level ? uniform_tile_edges(grid, per_tile, tx, tz) : std::nullopt) {
    out.draws.push_back({ix, iz, -1, 1, offset, tally.nearest, first.level, *edges});
    return;
  }
  out.culled += tally.culled;
  for (int row = 0; row < per_tile; ++row) {
    for (int col = 0; col < per_tile; ++col) {
      const ChunkState& chunk = grid.in_tile(tx, tz, col, row);
      if (chunk.visible)
        out.draws.push_back({ix, iz, row * per_tile + col, 1, offset, chunk.distance, chunk.level, chunk.coarser_edges});
    }
  }
}

}  // namespace

TileSelection select_tiles(const TileSelectionInput& in) {
  TileSelection out;
  if (in.patch_x_m <= 0.0f || in.patch_z_m <= 0.0f) return out;
  const TileWindow window = window_around_camera(in);
  // Levels for the whole chunk grid first, so balancing sees every neighbour.
  ChunkGrid grid(window);
  assign_levels_by_distance(grid, window, in);
  balance_neighbour_levels(grid);
  cull_chunks(grid, window, in);
  flag_coarser_neighbours(grid);

  const std::vector<char> in_block = select_far_blocks(grid, window, in, out);
  for (int tz = 0; tz < window.tiles_z; ++tz)
    for (int tx = 0; tx < window.tiles_x; ++tx)
      if (!in_block[static_cast<std::size_t>(tz) * window.tiles_x + tx]) select_tile_draws(grid, window, in, tx, tz, out);

  std::sort(out.draws.begin(), out.draws.end(),
            [](const TileDraw& a, const TileDraw& b) { return a.distance_m < b.distance_m; });
  return out;
}

}  // namespace ocean::render
