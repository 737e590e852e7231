// Which copies of the one periodic patch to draw this frame, and at which LOD. Each patch copy
// (tile) is split into chunks_per_side^2 chunks; chunks within the view distance are frustum-culled
// with a margin for wave height and displacement and get a level from their distance, balanced so
// neighbours differ by at most one (what the edge stitching handles). A tile whose chunks are all
// visible at one level is drawn whole (one draw call); near tiles are drawn chunk by chunk; and
// far_block_tiles^2 tiles all at the coarsest level are drawn as one far block.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "client/render/lod.hpp"

namespace ocean::render {

struct TileSelectionInput {
  glm::dvec3 camera_position{0.0};
  glm::mat4 clip_from_relative{1.0f};  // Camera::clip_from_relative
  float patch_x_m = 0.0f;
  float patch_z_m = 0.0f;
  float view_distance_m = 2500.0f;  // tiles whose nearest point is further are not drawn
  float max_height_m = 0.0f;        // vertical margin: largest |height| in the field
  float max_displacement_m = 0.0f;  // horizontal margin: largest |choppy displacement|
  int chunks_per_side = 1;          // LOD granularity: 2 lets the near tiles mix two levels
  int far_block_tiles = 1;          // > 1: blocks of this many tiles per side, aligned to multiples of it
  LodPolicy lod;
};

struct TileDraw {
  int ix = 0, iz = 0;           // tile index: the tile spans [ix, ix+1) * patch_x_m in x
  int chunk = -1;               // -1: the whole tile (or block); else row * chunks_per_side + col
  int span = 1;                 // tiles per side drawn: 1, or far_block_tiles for a far block
  glm::vec2 offset_relative{};  // tile origin minus camera position (x, z), metres
  float distance_m = 0.0f;      // from the eye to the nearest point drawn, at sea level
  int level = 0;
  unsigned coarser_edges = 0;   // TileEdge flags (of what is drawn) whose neighbour has level + 1
};

struct TileSelection {
  std::vector<TileDraw> draws;  // nearest first, so depth testing rejects hidden water early
  int culled = 0;               // chunks in range but outside the frustum
};

TileSelection select_tiles(const TileSelectionInput& input);

}  // namespace ocean::render
