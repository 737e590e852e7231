// Valid example values of every message, shared by the protocol tests; each test breaks one
// field of these to prove that exactly that field's rule rejects it.
#pragma once

#include <vector>

#include "frame_records.hpp"
#include "message_types.hpp"
#include "verify_message.hpp"

namespace ocean::protocol::test {

inline Bytes sample_cookie() { return Bytes{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}; }

inline StreamParams sample_stream() {
  StreamParams s;
  s.profile_id = 1;  // "mobile": 64 x 64, normals, not choppy
  s.grid = 64;
  s.patch_x_m = 256.0;
  s.patch_z_m = 128.0;
  s.gravity_mps2 = 9.81;
  s.depth_m = 0.0;
  s.rate_hz = 30;
  s.height_step_m = 0.01f;
  s.slope_step = 1.0f / 256;
  s.disp_step_m = 0.01f;
  s.normals = true;
  s.choppy = false;
  return s;
}

inline SceneParams sample_scene() {
  SceneParams s;
  s.size_x = 256;
  s.size_z = 128;
  s.patch_x_m = 256.0;
  s.patch_z_m = 128.0;
  s.spectrum = model::SpectrumKind::jonswap;
  s.spreading = model::SpreadingKind::hasselmann;
  s.wind_speed_mps = 12.5;
  s.wind_dir_deg = 30.0;
  s.fetch_m = 50000.0;
  s.amplitude = 0.75;
  s.depth_m = 40.0;
  s.small_wave_m = 0.1;
  s.choppiness = 1.2;
  s.gravity_mps2 = 9.81;
  s.seed = 0x1234'5678'9abc'def0ull;
  return s;
}

inline Welcome sample_welcome() {
  Welcome w;
  w.session_id = 0xfeed'beef'0000'0001ull;
  w.stream = sample_stream();
  w.scene = sample_scene();
  w.offered_profiles = {1, 2, 4};
  w.epoch_unix_ms = 1'763'700'000'000;
  w.current_tick = 5'000'000'123;  // past 2^32: ticks are 64-bit in version 2
  w.tick_period_s = 1.0 / 30.0;
  w.udp_port = 40123;
  w.udp_cookie = sample_cookie();
  w.max_message_bytes = 65536;
  w.scene_serial = 3;
  return w;
}

// The payload bytes of the sample records (any bytes: the protocol does not look inside).
inline std::span<const std::uint8_t> sample_payload() {
  static const Bytes payload{9, 8, 7, 6, 5, 4, 3, 2, 1, 0, 255};
  return payload;
}

// A frames block as the server sends it on a lossy link: a copy of the earlier, unacknowledged
// single-chunk delta of tick 999, then chunk 2 of 5 of the delta of tick 1000, oldest first.
inline std::vector<FrameRecord> sample_records() {
  return {FrameRecord{999, 998, false, 0, 1, sample_payload()}, FrameRecord{1000, 998, false, 2, 5, sample_payload()}};
}

inline FrameData sample_frame_data() { return FrameData{encode_frame_block(sample_records())}; }

inline ParamChange sample_param_change() {
  ParamChange p;
  p.admin_token = "s3cret";
  p.request_id = 77;
  p.wind_speed_mps = 15.0;
  p.choppiness = 0.5;
  p.spectrum = wire::Spectrum::phillips;
  return p;
}

// One valid value of each message type of version 2 with the side that sends it (FrameChunk and
// FrameBundle are version 1 only: a version-2 receiver refuses them, see test_malformed.cpp).
struct Sample {
  AnyMessage message;
  Sender sender;
};

inline std::vector<Sample> all_samples() {
  const Bytes cookie = sample_cookie();
  const std::uint64_t session = sample_welcome().session_id;
  return {
      {Hello{2, 5'000'000, wire::Transport::udp, "viewer-7 \xc3\xa9"}, Sender::client},
      {sample_welcome(), Sender::server},
      {UdpHello{session, cookie}, Sender::client},
      {UdpReady{session}, Sender::server},
      {Ack{session, cookie, 5'000'000'000ull, 0x8000'0005u}, Sender::client},
      {KeyframeRequest{session, cookie, wire::KeyframeReason::lost_baseline}, Sender::client},
      {SetTransport{wire::Transport::tcp}, Sender::client},
      {sample_param_change(), Sender::client},
      {SceneUpdate{77, 5'000'000'030ull, sample_scene(), 4}, Sender::server},
      {Error{Reason::profile_unavailable, "profile 3 is not offered; offered: 1 2 4"}, Sender::server},
      {Bye{wire::ByeReason::server_shutdown, "maintenance"}, Sender::server},
      {Ping{session, cookie, 42, 123'456'789'012ull}, Sender::client},
      {Pong{42, 123'456'789'012ull, 5'000'000'124ull, 1'763'700'033'366}, Sender::server},
      {sample_frame_data(), Sender::server},
      {HeightQuery{"s3cret", 12, 3, {wire::QueryPoint(10.5, -20.25), wire::QueryPoint(-1e4, 3e3)}}, Sender::client},
      {HeightAnswer{12, 5'000'000'031ull, 3,
                    {wire::SurfaceSample(0.75f, -0.1f, 0.99f, 0.05f, -0.3f), wire::SurfaceSample(-1.5f, 0.f, 1.f, 0.f, 0.f)}},
       Sender::server},
  };
}

inline VerifyOptions from(Sender sender, wire::Transport transport = wire::Transport::tcp) {
  VerifyOptions options;
  options.sender = sender;
  options.transport = transport;
  return options;
}

inline VerifyOptions from_server() { return from(Sender::server); }
inline VerifyOptions from_client() { return from(Sender::client); }

}  // namespace ocean::protocol::test
