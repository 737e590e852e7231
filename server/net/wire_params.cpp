#include "wire_params.hpp"

#include <cmath>

namespace ocean::server {

protocol::SceneParams wire_scene(const sim::SceneParams& s) {
  protocol::SceneParams w;
  w.size_x = static_cast<std::uint16_t>(s.size_x);
  w.size_z = static_cast<std::uint16_t>(s.size_z);
  w.patch_x_m = s.patch_x_m;
  w.patch_z_m = s.patch_z_m;
  w.spectrum = static_cast<wire::Spectrum>(s.spectrum);
  w.spreading = static_cast<wire::Spreading>(s.spreading);
  w.wind_speed_mps = s.wind_speed_mps;
  w.wind_dir_deg = s.wind_dir_deg;
  w.fetch_m = s.fetch_m;
  w.amplitude = s.amplitude;
  w.depth_m = std::isinf(s.depth_m) ? 0.0 : s.depth_m;  // 0 on the wire = deep water
  w.small_wave_m = s.small_wave_m;
  w.choppiness = s.choppiness;
  w.gravity_mps2 = s.gravity_mps2;
  w.seed = s.seed;
  return w;
}

protocol::StreamParams wire_stream(const codec::StreamConfig& c) {
  return protocol::StreamParams{c.profile_id, c.grid, c.patch_x_m, c.patch_z_m, c.gravity_mps2, c.depth_m, c.rate_hz,
                                c.height_step_m, c.slope_step, c.disp_step_m, c.normals, c.choppy};
}

}  // namespace ocean::server
