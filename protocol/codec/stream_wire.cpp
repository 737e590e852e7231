#include "stream_wire.hpp"

#include <cmath>

namespace ocean::codec {

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
  to.wake = from.wake;
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

}  // namespace ocean::codec
