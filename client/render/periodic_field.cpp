#include "client/render/periodic_field.hpp"

namespace ocean::render {

void expand_periodic(int n, std::initializer_list<const float*> fields, std::vector<float>& out) {
  expand_periodic_strided(n, 1, 1, fields, out);
}

void expand_periodic_strided(int n, int stride, int repeats, std::initializer_list<const float*> fields,
                             std::vector<float>& out) {
  const int side = repeats * (n / stride) + 1;
  out.resize(static_cast<std::size_t>(side) * side * fields.size());
  float* dst = out.data();
  for (int row = 0; row < side; ++row) {
    const std::size_t src_row = static_cast<std::size_t>((row * stride) % n) * n;
    for (int col = 0; col < side; ++col) {
      const std::size_t src = src_row + (col * stride) % n;
      for (const float* f : fields) *dst++ = f[src];
    }
  }
}

void central_difference_slopes(int n, float patch_x_m, float patch_z_m, const float* height,
                               std::vector<float>& slope_x, std::vector<float>& slope_z) {
  const std::size_t count = static_cast<std::size_t>(n) * n;
  slope_x.resize(count);
  slope_z.resize(count);
  const float inv_2dx = n / (2.0f * patch_x_m), inv_2dz = n / (2.0f * patch_z_m);
  const auto h = [&](int row, int col) { return height[((row + n) % n) * n + (col + n) % n]; };
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      slope_x[r * n + c] = (h(r, c + 1) - h(r, c - 1)) * inv_2dx;
      slope_z[r * n + c] = (h(r + 1, c) - h(r - 1, c)) * inv_2dz;
    }
  }
}

SlopePointers slopes_or_differences(int n, float patch_x_m, float patch_z_m, const float* height,
                                    const float* slope_x, const float* slope_z, std::vector<float>& scratch_x,
                                    std::vector<float>& scratch_z) {
  if (slope_x && slope_z) return {slope_x, slope_z};
  central_difference_slopes(n, patch_x_m, patch_z_m, height, scratch_x, scratch_z);
  return {scratch_x.data(), scratch_z.data()};
}

}  // namespace ocean::render
