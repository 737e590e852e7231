#include "cascade_scene.hpp"

#include "spectrum.hpp"

#include <string>

namespace ocean::sim {

SceneParams cascade_scene(const SceneParams& scene, const Cascade& cascade, int index) {
  const std::string problem = cascade_problem(cascade);
  if (!problem.empty()) throw ParamError("cascade " + std::to_string(index) + ": " + problem);
  SceneParams p = scene;
  p.small_wave_m = scene.small_wave_m > 0.0 ? scene.small_wave_m : default_small_wave(scene);
  p.patch_x_m = scene.patch_x_m * cascade.patch_scale;
  p.patch_z_m = scene.patch_z_m * cascade.patch_scale;
  p.size_x = p.size_z = cascade.grid;
  p.seed = cascade_seed(scene.seed, index);
  p.band = cascade.band;
  const std::string error = validate(p);
  if (!error.empty()) throw ParamError("cascade " + std::to_string(index) + ": " + error);
  return p;
}

void append_cascade_frame(Frame& out, const Frame& part) {
  std::vector<float>* to[] = {&out.height, &out.slope_x, &out.slope_z, &out.disp_x, &out.disp_z,
                              &out.disp_xx, &out.disp_zz, &out.disp_xz, &out.jacobian};
  const std::vector<float>* from[] = {&part.height, &part.slope_x, &part.slope_z, &part.disp_x, &part.disp_z,
                                      &part.disp_xx, &part.disp_zz, &part.disp_xz, &part.jacobian};
  for (std::size_t f = 0; f < std::size(to); ++f) to[f]->insert(to[f]->end(), from[f]->begin(), from[f]->end());
}

}  // namespace ocean::sim
