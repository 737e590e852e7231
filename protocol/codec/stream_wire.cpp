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

namespace {

// StreamParams and StreamConfig hold the same fields (the config adds the tick rate, which the
// Welcome carries as tick_period_s): one list for both directions.
template <typename From, typename To>
void copy_stream_fields(const From& from, To& to) {
  to.profile_id = from.profile_id;
  copy_profile_fields(from, to);
  to.patch_x_m = from.patch_x_m;
  to.patch_z_m = from.patch_z_m;
  to.gravity_mps2 = from.gravity_mps2;
  to.depth_m = from.depth_m;
}

}  // namespace

protocol::StreamParams wire_stream(const StreamConfig& config) {
  protocol::StreamParams s;
  copy_stream_fields(config, s);
  return s;
}

StreamConfig decoder_config(const protocol::Welcome& welcome) {
  StreamConfig c;
  copy_stream_fields(welcome.stream, c);
  // The codec advances its state one server tick per step: a stream slower than its server
  // (lite at 15 Hz under 30 Hz ticks) carries every n-th tick, so it needs the tick rate too.
  c.tick_rate_hz = welcome.tick_period_s > 0 ? static_cast<std::uint16_t>(std::lround(1.0 / welcome.tick_period_s)) : 0;
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
  m.choppiness = s.choppiness;
  return m;
}

}  // namespace ocean::codec
