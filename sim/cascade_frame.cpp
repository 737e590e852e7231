#include "cascade_frame.hpp"

namespace ocean::sim {

void append_cascade_frame(Frame& out, const Frame& part) {
  std::vector<float>* to[] = {&out.height, &out.slope_x, &out.slope_z, &out.disp_x, &out.disp_z,
                              &out.disp_xx, &out.disp_zz, &out.disp_xz, &out.jacobian};
  const std::vector<float>* from[] = {&part.height, &part.slope_x, &part.slope_z, &part.disp_x, &part.disp_z,
                                      &part.disp_xx, &part.disp_zz, &part.disp_xz, &part.jacobian};
  for (std::size_t f = 0; f < std::size(to); ++f) to[f]->insert(to[f]->end(), from[f]->begin(), from[f]->end());
}

}  // namespace ocean::sim
