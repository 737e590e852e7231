#include "cascade_set.hpp"

namespace ocean::sim {

CascadeSet::CascadeSet(const SceneParams& scene, std::span<const Cascade> cascades) {
  oceans_.reserve(cascades.size());
  for (std::size_t i = 0; i < cascades.size(); ++i)
    oceans_.emplace_back(model::cascade_scene(scene, cascades[i], static_cast<int>(i)));
}

void CascadeSet::evaluate(double t, Frame& out, FrameRequest request) {
  // Emptied, not freed: a frame handed back for reuse keeps its capacity, so a steady stream of
  // ticks copies each cascade once and allocates nothing.
  for (const auto field : kFrameFields) (out.*field).clear();
  for (Ocean& ocean : oceans_) {
    ocean.evaluate(t, part_, request);
    append_cascade_frame(out, part_);
  }
  if (!oceans_.empty()) {
    const SceneParams& first = oceans_.front().params();
    out.n_x = first.size_x;  // the first lattice's; the fields hold every lattice's samples
    out.n_z = first.size_z;
    out.patch_x_m = first.patch_x_m;
    out.patch_z_m = first.patch_z_m;
  }
  out.time_s = t;
}

}  // namespace ocean::sim
