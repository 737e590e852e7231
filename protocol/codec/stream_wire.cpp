#include "stream_wire.hpp"

#include <cmath>

namespace ocean::codec {

// Wire and model enums are the same numbers: a new spectrum or spreading function must be added
// to both (and to the scene model's formulas) together.
static_assert(static_cast<int>(wire::Spectrum::phillips) == static_cast<int>(ModelSpectrum::phillips));
static_assert(static_cast<int>(wire::Spectrum::jonswap) == static_cast<int>(ModelSpectrum::jonswap));
static_assert(static_cast<int>(wire::Spreading::cos2s) == static_cast<int>(ModelSpreading::cos2s));
static_assert(static_cast<int>(wire::Spreading::donelan_banner) == static_cast<int>(ModelSpreading::donelan_banner));
static_assert(static_cast<int>(wire::Spreading::hasselmann) == static_cast<int>(ModelSpreading::hasselmann));

StreamConfig decoder_config(const protocol::Welcome& welcome) {
  const protocol::StreamParams& s = welcome.stream;
  StreamConfig c;
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

SceneModelParams scene_model_params(const protocol::SceneParams& s) {
  SceneModelParams m;
  m.size_x = s.size_x;
  m.size_z = s.size_z;
  m.patch_x_m = s.patch_x_m;
  m.patch_z_m = s.patch_z_m;
  m.spectrum = static_cast<ModelSpectrum>(s.spectrum);
  m.spreading = static_cast<ModelSpreading>(s.spreading);
  m.wind_speed_mps = s.wind_speed_mps;
  m.wind_dir_deg = s.wind_dir_deg;
  m.fetch_m = s.fetch_m;
  m.amplitude = s.amplitude;
  m.depth_m = s.depth_m;  // 0 = deep water on the wire and in the model
  m.small_wave_m = s.small_wave_m;
  m.gravity_mps2 = s.gravity_mps2;
  m.seed = s.seed;
  return m;
}

}  // namespace ocean::codec
