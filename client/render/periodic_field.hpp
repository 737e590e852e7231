// CPU-side preparation of the streamed per-sample fields: the n x n periodic samples become the
// (n+1) x (n+1) vertex streams of the grid (the extra row/column wraps to the first), and slopes
// are derived from heights for streams that carry no normals.
#pragma once

#include <initializer_list>
#include <vector>

namespace ocean::render {

// Interleaves the given n x n fields (row-major, rows along +z) into (n+1)^2 vertices, the last
// row and column repeating the first, so neighbouring tiles share their edge samples exactly.
void expand_periodic(int n, std::initializer_list<const float*> fields, std::vector<float>& out);

// The same for a far block: every stride-th sample, the patch repeated `repeats` times per side,
// giving (repeats * n / stride + 1)^2 vertices. stride must divide n.
void expand_periodic_strided(int n, int stride, int repeats, std::initializer_list<const float*> fields,
                             std::vector<float>& out);

// dh/dx and dh/dz by central differences over the periodic field, spacing patch / n.
void central_difference_slopes(int n, float patch_x_m, float patch_z_m, const float* height,
                               std::vector<float>& slope_x, std::vector<float>& slope_z);

// The slopes to draw: slope_x and slope_z when both are given, else central differences of the
// heights made in scratch_x, scratch_z (a stream without normals still shades).
struct SlopePointers {
  const float* x;
  const float* z;
};
SlopePointers slopes_or_differences(int n, float patch_x_m, float patch_z_m, const float* height,
                                    const float* slope_x, const float* slope_z, std::vector<float>& scratch_x,
                                    std::vector<float>& scratch_z);

}  // namespace ocean::render
