// Level-of-detail policy for ocean tiles: level L draws the patch grid at vertex stride 2^L.
// The level grows by one each time the tile distance doubles past lod0_distance_m, so the
// on-screen triangle size stays roughly constant.
#pragma once

namespace ocean::render {

struct LodPolicy {
  float lod0_distance_m = 256.0f;  // tiles nearer than this use the full grid
  int max_level = 3;               // coarsest level (stride 2^max_level)
};

// Non-decreasing in distance_m; 0 below lod0_distance_m, then +1 per doubling, capped.
int lod_level_for_distance(float distance_m, const LodPolicy& policy);

// The coarsest level a block of grid_n cells supports, at most wanted: level L needs grid_n
// divisible by 2^L, which is also what stitching a level-(L-1) neighbour to it needs.
int supported_lod_levels(int grid_n, int wanted_max_level);

inline int lod_stride(int level) { return 1 << level; }

}  // namespace ocean::render
