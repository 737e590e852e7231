#include "cascade_scene.hpp"

#include "spectrum.hpp"

#include <string>

namespace ocean::model {

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

}  // namespace ocean::model
