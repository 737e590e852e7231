// Frame: one evaluated tick of the ocean, row-major with z as rows and x as columns.
#pragma once

#include <vector>

namespace ocean::sim {

struct Frame {
  int n_x = 0;
  int n_z = 0;
  double patch_x_m = 0.0;
  double patch_z_m = 0.0;
  double time_s = 0.0;
  std::vector<float> height;    // metres, index z * n_x + x
  std::vector<float> slope_x;   // dh/dx, empty unless requested
  std::vector<float> slope_z;   // dh/dz, empty unless requested
  std::vector<float> disp_x;    // choppy displacement in metres (lambda applied), empty unless choppy
  std::vector<float> disp_z;
  // Choppy: the displacement's derivatives dDx/dx, dDz/dz, dDx/dz (lambda applied), the inputs of
  // the Jacobian (1 + xx)(1 + zz) - xz^2 of the displaced grid; < ~0.3 means folding (foam).
  std::vector<float> disp_xx, disp_zz, disp_xz;
  std::vector<float> jacobian;
};

}  // namespace ocean::sim
