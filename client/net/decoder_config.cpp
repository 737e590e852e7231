#include "decoder_config.hpp"

#include <cmath>

namespace ocean::client {

codec::StreamConfig decoder_config(const protocol::Welcome& welcome) {
  const protocol::StreamParams& s = welcome.stream;
  codec::StreamConfig c;
  c.profile_id = s.profile_id;
  c.grid = s.grid;
  c.patch_x_m = s.patch_x_m;
  c.patch_z_m = s.patch_z_m;
  c.gravity_mps2 = s.gravity_mps2;
  c.depth_m = s.depth_m;
  c.rate_hz = s.rate_hz;
  // The codec advances its state one server tick per step: a stream slower than its server
  // (lite at 15 Hz under 30 Hz ticks) carries every n-th tick, so it needs the tick rate too.
  c.tick_rate_hz = welcome.tick_period_s > 0 ? static_cast<std::uint16_t>(std::lround(1.0 / welcome.tick_period_s)) : 0;
  c.height_step_m = s.height_step_m;
  c.slope_step = s.slope_step;
  c.disp_step_m = s.disp_step_m;
  c.normals = s.normals;
  c.choppy = s.choppy;
  return c;
}

}  // namespace ocean::client
