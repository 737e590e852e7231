#include "client/render/tile_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "client/render/frustum.hpp"
#include "client/render/grid_mesh.hpp"

namespace ocean::render {

namespace {

// Distance from a point to the interval [lo, hi] along one axis.
double gap(double p, double lo, double hi) { return p < lo ? lo - p : (p > hi ? p - hi : 0.0); }

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct ChunkState {
  float distance = 0.0f;
  int level = 0;
  bool in_range = false;
  bool visible = false;  // in range and possibly inside the frustum
  unsigned coarser_edges = 0;
};

}  // namespace

TileSelection select_tiles(const TileSelectionInput& in) {
  TileSelection out;
  if (in.patch_x_m <= 0.0f || in.patch_z_m <= 0.0f) return out;
  const int c = std::max(1, in.chunks_per_side);
  const double px = in.patch_x_m, pz = in.patch_z_m, chx = px / c, chz = pz / c;
  const glm::dvec3 eye = in.camera_position;
  const int cx = static_cast<int>(std::floor(eye.x / px));
  const int cz = static_cast<int>(std::floor(eye.z / pz));
  const int rx = static_cast<int>(std::ceil(in.view_distance_m / px)) + 1;
  const int rz = static_cast<int>(std::ceil(in.view_distance_m / pz)) + 1;
  const int tiles_x = 2 * rx + 1, tiles_z = 2 * rz + 1;
  const int wx = tiles_x * c, wz = tiles_z * c;  // chunk grid over the square of tiles
  const double x_origin = (cx - rx) * px, z_origin = (cz - rz) * pz;

  // Levels for the whole chunk grid first, so balancing sees every neighbour.
  std::vector<ChunkState> chunk(static_cast<std::size_t>(wx) * wz);
  const auto at = [&](int gx, int gz) -> ChunkState& { return chunk[static_cast<std::size_t>(gz) * wx + gx]; };
  const auto distance_to = [&](double x0, double z0, double w, double d) {
    const double dx = gap(eye.x, x0, x0 + w), dz = gap(eye.z, z0, z0 + d);
    return static_cast<float>(std::sqrt(dx * dx + dz * dz + eye.y * eye.y));
  };
  for (int gz = 0; gz < wz; ++gz) {
    for (int gx = 0; gx < wx; ++gx) {
      ChunkState& s = at(gx, gz);
      s.distance = distance_to(x_origin + gx * chx, z_origin + gz * chz, chx, chz);
      // Chunk-level detail only where it pays (the tile would be at level 0 or 1); further out
      // the whole tile shares one level so it stays one draw call.
      const int tile_level = lod_level_for_distance(
          distance_to(x_origin + (gx / c) * px, z_origin + (gz / c) * pz, px, pz), in.lod);
      s.level = tile_level <= 1 ? lod_level_for_distance(s.distance, in.lod) : tile_level;
    }
  }
  // Restricted-quadtree style balance: a chunk may be at most one level coarser than any neighbour.
  for (bool changed = true; changed;) {
    changed = false;
    for (int gz = 0; gz < wz; ++gz) {
      for (int gx = 0; gx < wx; ++gx) {
        int limit = at(gx, gz).level;
        if (gx > 0) limit = std::min(limit, at(gx - 1, gz).level + 1);
        if (gx + 1 < wx) limit = std::min(limit, at(gx + 1, gz).level + 1);
        if (gz > 0) limit = std::min(limit, at(gx, gz - 1).level + 1);
        if (gz + 1 < wz) limit = std::min(limit, at(gx, gz + 1).level + 1);
        if (limit < at(gx, gz).level) {
          at(gx, gz).level = limit;
          changed = true;
        }
      }
    }
  }

  const Frustum frustum = Frustum::from_clip_matrix(in.clip_from_relative);
  const float margin_xz = in.max_displacement_m;
  const float margin_y = in.max_height_m + in.max_displacement_m;
  for (int gz = 0; gz < wz; ++gz) {
    for (int gx = 0; gx < wx; ++gx) {
      ChunkState& s = at(gx, gz);
      const double horizontal = std::sqrt(std::max(0.0, double(s.distance) * s.distance - eye.y * eye.y));
      s.in_range = horizontal <= in.view_distance_m;
      if (!s.in_range) continue;
      const float x0 = static_cast<float>(x_origin + gx * chx - eye.x), z0 = static_cast<float>(z_origin + gz * chz - eye.z);
      const Aabb box{{x0 - margin_xz, static_cast<float>(-margin_y - eye.y), z0 - margin_xz},
                     {x0 + static_cast<float>(chx) + margin_xz, static_cast<float>(margin_y - eye.y),
                      z0 + static_cast<float>(chz) + margin_xz}};
      s.visible = frustum.may_see(box);
    }
  }
  for (int gz = 0; gz < wz; ++gz) {
    for (int gx = 0; gx < wx; ++gx) {
      ChunkState& s = at(gx, gz);
      if (gz > 0 && at(gx, gz - 1).level > s.level) s.coarser_edges |= kEdgeMinZ;
      if (gz + 1 < wz && at(gx, gz + 1).level > s.level) s.coarser_edges |= kEdgeMaxZ;
      if (gx > 0 && at(gx - 1, gz).level > s.level) s.coarser_edges |= kEdgeMinX;
      if (gx + 1 < wx && at(gx + 1, gz).level > s.level) s.coarser_edges |= kEdgeMaxX;
    }
  }

  // Far blocks: every chunk at the coarsest level (tiles outside the window are beyond the view
  // distance, so they count as coarsest too). A block never needs stitching: nothing is coarser.
  std::vector<char> in_block(static_cast<std::size_t>(tiles_x) * tiles_z, 0);
  const int span = std::max(1, in.far_block_tiles);
  if (span > 1) {
    for (int bz = floor_div(cz - rz, span); bz <= floor_div(cz + rz, span); ++bz) {
      for (int bx = floor_div(cx - rx, span); bx <= floor_div(cx + rx, span); ++bx) {
        bool coarsest = true, any_visible = false;
        int culled = 0;
        float nearest = std::numeric_limits<float>::max();
        for (int iz = bz * span; iz < (bz + 1) * span && coarsest; ++iz) {
          for (int ix = bx * span; ix < (bx + 1) * span && coarsest; ++ix) {
            const int tx = ix - (cx - rx), tz = iz - (cz - rz);
            if (tx < 0 || tz < 0 || tx >= tiles_x || tz >= tiles_z) continue;
            for (int g = 0; g < c * c; ++g) {
              const ChunkState& s = at(tx * c + g % c, tz * c + g / c);
              coarsest = coarsest && s.level == in.lod.max_level;
              any_visible = any_visible || s.visible;
              culled += s.in_range && !s.visible;
              if (s.visible) nearest = std::min(nearest, s.distance);
            }
          }
        }
        if (!coarsest || !any_visible) continue;
        for (int iz = bz * span; iz < (bz + 1) * span; ++iz) {
          for (int ix = bx * span; ix < (bx + 1) * span; ++ix) {
            const int tx = ix - (cx - rx), tz = iz - (cz - rz);
            if (tx >= 0 && tz >= 0 && tx < tiles_x && tz < tiles_z) in_block[static_cast<std::size_t>(tz) * tiles_x + tx] = 1;
          }
        }
        out.culled += culled;
        const glm::vec2 offset{static_cast<float>(bx * span * px - eye.x), static_cast<float>(bz * span * pz - eye.z)};
        out.draws.push_back({bx * span, bz * span, -1, span, offset, nearest, in.lod.max_level, 0u});
      }
    }
  }

  // One draw per tile where its chunks agree (same level, each side stitched alike), else per chunk.
  for (int tz = 0; tz < tiles_z; ++tz) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      if (in_block[static_cast<std::size_t>(tz) * tiles_x + tx]) continue;
      const int ix = cx - rx + tx, iz = cz - rz + tz;
      const glm::vec2 offset{static_cast<float>(ix * px - eye.x), static_cast<float>(iz * pz - eye.z)};
      // A tile with any visible chunk is drawn; whole if its chunks agree, even if some of them
      // are just outside the view (clipping them costs less than extra draw calls).
      const ChunkState& first = at(tx * c, tz * c);
      bool whole = true, any_visible = false;
      int culled = 0;
      float nearest = std::numeric_limits<float>::max();
      for (int j = 0; j < c; ++j) {
        for (int i = 0; i < c; ++i) {
          const ChunkState& s = at(tx * c + i, tz * c + j);
          whole = whole && s.level == first.level;
          any_visible = any_visible || s.visible;
          culled += s.in_range && !s.visible;
          if (s.visible) nearest = std::min(nearest, s.distance);
        }
      }
      if (!any_visible) {
        out.culled += culled;
        continue;
      }
      unsigned mask = 0;
      const unsigned bits[4] = {kEdgeMinZ, kEdgeMaxX, kEdgeMaxZ, kEdgeMinX};
      for (int e = 0; e < 4 && whole; ++e) {
        for (int k = 0; k < c; ++k) {
          const int i = e == 1 ? c - 1 : (e == 3 ? 0 : k);
          const int j = e == 0 ? 0 : (e == 2 ? c - 1 : k);
          const unsigned flag = at(tx * c + i, tz * c + j).coarser_edges & bits[e];
          if (k > 0 && flag != (mask & bits[e])) whole = false;
          mask |= flag;
        }
      }
      if (whole) {
        out.draws.push_back({ix, iz, -1, 1, offset, nearest, first.level, mask});
        continue;
      }
      out.culled += culled;
      for (int j = 0; j < c; ++j) {
        for (int i = 0; i < c; ++i) {
          const ChunkState& s = at(tx * c + i, tz * c + j);
          if (s.visible) out.draws.push_back({ix, iz, j * c + i, 1, offset, s.distance, s.level, s.coarser_edges});
        }
      }
    }
  }
  std::sort(out.draws.begin(), out.draws.end(),
            [](const TileDraw& a, const TileDraw& b) { return a.distance_m < b.distance_m; });
  return out;
}

}  // namespace ocean::render
