// Builds each message with the generated FlatBuffers builders and finishes it size-prefixed.
#include "message_builders.hpp"

#include <stdexcept>

#include <algorithm>
#include <stdexcept>

#include "protocol_version.hpp"
#include "wire_limits.hpp"

namespace ocean::protocol {
namespace {

using flatbuffers::FlatBufferBuilder;
using flatbuffers::Offset;

template <typename T>
Bytes finish(FlatBufferBuilder& fbb, wire::Body type, Offset<T> body) {
  wire::MessageBuilder root(fbb);
  root.add_version(kProtocolVersion);
  root.add_body_type(type);
  root.add_body(body.Union());
  wire::FinishSizePrefixedMessageBuffer(fbb, root.Finish());
  return Bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
}

// Empty vectors and strings are left out: the reader treats absent and empty alike.
Offset<flatbuffers::Vector<std::uint8_t>> bytes_of(FlatBufferBuilder& fbb,
                                                   std::span<const std::uint8_t> bytes) {
  return bytes.empty() ? 0 : fbb.CreateVector(bytes.data(), bytes.size());
}

Offset<flatbuffers::String> string_of(FlatBufferBuilder& fbb, const std::string& text) {
  return text.empty() ? 0 : fbb.CreateString(text);
}

Offset<wire::StreamParams> stream_of(FlatBufferBuilder& fbb, const StreamParams& s) {
  Offset<flatbuffers::Vector<const wire::Cascade*>> cascades = 0;
  if (!s.cascades.empty()) {
    std::vector<wire::Cascade> out;
    for (const Cascade& c : s.cascades)
      out.emplace_back(static_cast<std::uint8_t>(c.patch_scale), static_cast<std::uint16_t>(c.grid),
                       static_cast<std::uint16_t>(c.band.min_cycles), static_cast<std::uint16_t>(c.band.max_cycles));
    cascades = fbb.CreateVectorOfStructs(out);
  }
  Offset<wire::WakeLattice> wake = 0;
  if (s.wake.grid != 0)
    wake = wire::CreateWakeLattice(fbb, static_cast<std::uint16_t>(s.wake.grid), s.wake.size_m, s.wake.origin_x_m,
                                   s.wake.origin_z_m, s.wake.decay_per_s, s.wake.viscosity_m2ps, s.wake.epoch_ticks);
  wire::StreamParamsBuilder b(fbb);
  b.add_profile_id(s.profile_id);
  b.add_grid(s.grid);
  b.add_patch_x_m(s.patch_x_m);
  b.add_patch_z_m(s.patch_z_m);
  b.add_gravity_mps2(s.gravity_mps2);
  b.add_depth_m(s.depth_m);
  b.add_rate_hz(s.rate_hz);
  b.add_height_step_m(s.height_step_m);
  b.add_slope_step(s.slope_step);
  b.add_disp_step_m(s.disp_step_m);
  b.add_normals(s.normals);
  b.add_choppy(s.choppy);
  if (!s.cascades.empty()) b.add_cascades(cascades);
  if (s.wake.grid != 0) b.add_wake(wake);
  return b.Finish();
}

Offset<flatbuffers::Vector<Offset<wire::Vessel>>> vessels_of(FlatBufferBuilder& fbb,
                                                              const std::vector<model::VesselTrack>& vessels) {
  std::vector<Offset<wire::Vessel>> out;
  for (const model::VesselTrack& v : vessels) {
    std::vector<wire::Waypoint> points;
    for (const model::Waypoint& p : v.points) points.emplace_back(p.t_s, p.x_m, p.z_m);
    out.push_back(wire::CreateVessel(fbb, v.id, v.hull.length_m, v.hull.beam_m, v.hull.draft_m, v.repeat,
                                     fbb.CreateVectorOfStructs(points), v.presence.from_s, v.presence.for_s,
                                     v.presence.every_s));
  }
  return fbb.CreateVector(out);
}

Offset<wire::SceneParams> scene_of(FlatBufferBuilder& fbb, const SceneParams& s) {
  wire::SceneParamsBuilder b(fbb);
  // 16 bits hold every valid size; the enums have the model's numbers (protocol/scene_wire checks).
  b.add_size_x(static_cast<std::uint16_t>(s.size_x));
  b.add_size_z(static_cast<std::uint16_t>(s.size_z));
  b.add_patch_x_m(s.patch_x_m);
  b.add_patch_z_m(s.patch_z_m);
  b.add_spectrum(static_cast<wire::Spectrum>(s.spectrum));
  b.add_spreading(static_cast<wire::Spreading>(s.spreading));
  b.add_wind_speed_mps(s.wind_speed_mps);
  b.add_wind_dir_deg(s.wind_dir_deg);
  b.add_fetch_m(s.fetch_m);
  b.add_amplitude(s.amplitude);
  b.add_depth_m(model::wire_depth(s.depth_m));
  b.add_small_wave_m(s.small_wave_m);
  b.add_choppiness(s.choppiness);
  b.add_gravity_mps2(s.gravity_mps2);
  b.add_seed(s.seed);
  return b.Finish();
}

}  // namespace

Bytes encode(const Hello& m) {
  FlatBufferBuilder fbb(128);
  const auto name = string_of(fbb, m.client_name);
  wire::HelloBuilder b(fbb);
  b.add_profile_id(m.profile_id);
  b.add_bandwidth_bps(m.bandwidth_bps);
  b.add_transport(m.transport);
  b.add_client_name(name);
  return finish(fbb, wire::Body::Hello, b.Finish());
}

Bytes encode(const Welcome& m) {
  FlatBufferBuilder fbb(512);
  const auto stream = stream_of(fbb, m.stream);
  const auto scene = scene_of(fbb, m.scene);
  const auto offered = bytes_of(fbb, m.offered_profiles);
  const auto cookie = bytes_of(fbb, m.udp_cookie);
  const auto vessels = m.vessels.empty() ? 0 : vessels_of(fbb, m.vessels);
  wire::WelcomeBuilder b(fbb);
  b.add_session_id(m.session_id);
  b.add_stream(stream);
  b.add_scene(scene);
  b.add_offered_profiles(offered);
  b.add_epoch_unix_ms(m.epoch_unix_ms);
  b.add_current_tick64(m.current_tick);
  b.add_scene_serial(m.scene_serial);
  b.add_tick_period_s(m.tick_period_s);
  b.add_udp_port(m.udp_port);
  b.add_udp_cookie(cookie);
  b.add_max_message_bytes(m.max_message_bytes);
  if (!m.vessels.empty()) b.add_vessels(vessels);
  return finish(fbb, wire::Body::Welcome, b.Finish());
}

Bytes encode(const UdpHello& m) {
  // Padding = what the message lacks to reach the minimum; the vector's own 4-byte length and
  // alignment are absorbed by measuring once without padding.
  auto build = [&](std::size_t padding_bytes) {
    FlatBufferBuilder fbb(kUdpHelloMinBytes + 64);
    const auto cookie = bytes_of(fbb, m.cookie);
    const std::vector<std::uint8_t> zeros(padding_bytes, 0);
    const auto padding = fbb.CreateVector(zeros);
    wire::UdpHelloBuilder b(fbb);
    b.add_session_id(m.session_id);
    b.add_cookie(cookie);
    b.add_padding(padding);
    return finish(fbb, wire::Body::UdpHello, b.Finish());
  };
  Bytes bytes = build(0);
  if (bytes.size() < kUdpHelloMinBytes) bytes = build(kUdpHelloMinBytes - bytes.size());
  return bytes;
}

Bytes encode(const UdpReady& m) {
  FlatBufferBuilder fbb(64);
  wire::UdpReadyBuilder b(fbb);
  b.add_session_id(m.session_id);
  return finish(fbb, wire::Body::UdpReady, b.Finish());
}


Bytes encode(const FrameData& m) {
  FlatBufferBuilder fbb(m.frames.size() + 64);
  const auto frames = fbb.CreateVector(m.frames);  // required: written even when empty
  wire::FrameDataBuilder b(fbb);
  b.add_frames(frames);
  return finish(fbb, wire::Body::FrameData, b.Finish());
}

Bytes encode(const Ack& m) {
  FlatBufferBuilder fbb(128);
  const auto cookie = bytes_of(fbb, m.cookie);
  wire::AckBuilder b(fbb);
  b.add_session_id(m.session_id);
  b.add_cookie(cookie);
  b.add_latest_tick64(m.latest_tick);
  b.add_ack_bits(m.ack_bits);
  return finish(fbb, wire::Body::Ack, b.Finish());
}

Bytes encode(const KeyframeRequest& m) {
  FlatBufferBuilder fbb(128);
  const auto cookie = bytes_of(fbb, m.cookie);
  wire::KeyframeRequestBuilder b(fbb);
  b.add_session_id(m.session_id);
  b.add_cookie(cookie);
  b.add_reason(m.reason);
  return finish(fbb, wire::Body::KeyframeRequest, b.Finish());
}

Bytes encode(const SetTransport& m) {
  FlatBufferBuilder fbb(64);
  wire::SetTransportBuilder b(fbb);
  b.add_transport(m.transport);
  return finish(fbb, wire::Body::SetTransport, b.Finish());
}

Bytes encode(const ParamChange& m) {
  FlatBufferBuilder fbb(256);
  const auto token = string_of(fbb, m.admin_token);
  Offset<wire::VesselCommand> vessel = 0;
  if (const auto& v = m.vessel)
    vessel = wire::CreateVesselCommand(fbb, v->action, v->id, v->hull.length_m, v->hull.beam_m, v->hull.draft_m, v->x_m,
                                       v->z_m, v->heading_deg, v->speed_mps, v->size_m);
  wire::ParamChangeBuilder b(fbb);
  if (m.vessel) b.add_vessel(vessel);
  b.add_admin_token(token);
  b.add_request_id(m.request_id);
  if (m.wind_speed_mps) b.add_wind_speed_mps(*m.wind_speed_mps);
  if (m.wind_dir_deg) b.add_wind_dir_deg(*m.wind_dir_deg);
  if (m.amplitude) b.add_amplitude(*m.amplitude);
  if (m.choppiness) b.add_choppiness(*m.choppiness);
  if (m.spectrum) b.add_spectrum(*m.spectrum);
  return finish(fbb, wire::Body::ParamChange, b.Finish());
}

Bytes encode(const SceneUpdate& m) {
  FlatBufferBuilder fbb(256);
  const auto scene = scene_of(fbb, m.scene);
  const auto vessels = m.vessels ? vessels_of(fbb, *m.vessels) : 0;
  wire::SceneUpdateBuilder b(fbb);
  if (m.vessels) b.add_vessels(vessels);
  b.add_request_id(m.request_id);
  b.add_effective_tick64(m.effective_tick);
  b.add_serial(m.serial);
  b.add_scene(scene);
  return finish(fbb, wire::Body::SceneUpdate, b.Finish());
}

Bytes encode(const Error& m) {
  FlatBufferBuilder fbb(128 + m.text.size());
  const auto text = string_of(fbb, m.text);
  wire::ErrorBuilder b(fbb);
  b.add_code(to_wire(m.code));
  b.add_text(text);
  return finish(fbb, wire::Body::Error, b.Finish());
}

Bytes encode(const Bye& m) {
  FlatBufferBuilder fbb(128 + m.text.size());
  const auto text = string_of(fbb, m.text);
  wire::ByeBuilder b(fbb);
  b.add_reason(m.reason);
  b.add_text(text);
  return finish(fbb, wire::Body::Bye, b.Finish());
}

Bytes encode(const Ping& m) {
  FlatBufferBuilder fbb(128);
  const auto cookie = bytes_of(fbb, m.cookie);
  wire::PingBuilder b(fbb);
  b.add_session_id(m.session_id);
  b.add_cookie(cookie);
  b.add_seq(m.seq);
  b.add_client_time_us(m.client_time_us);
  return finish(fbb, wire::Body::Ping, b.Finish());
}

Bytes encode(const Pong& m) {
  FlatBufferBuilder fbb(64);
  wire::PongBuilder b(fbb);
  b.add_seq(m.seq);
  b.add_client_time_us(m.client_time_us);
  b.add_server_tick64(m.server_tick);
  b.add_server_time_unix_ms(m.server_time_unix_ms);
  return finish(fbb, wire::Body::Pong, b.Finish());
}

Bytes encode(const HeightQuery& m) {
  FlatBufferBuilder fbb(128 + m.points.size() * sizeof(wire::QueryPoint));
  const auto token = string_of(fbb, m.admin_token);
  const auto points = fbb.CreateVectorOfStructs(m.points);
  wire::HeightQueryBuilder b(fbb);
  b.add_admin_token(token);
  b.add_request_id(m.request_id);
  b.add_profile_id(m.profile_id);
  b.add_points(points);
  return finish(fbb, wire::Body::HeightQuery, b.Finish());
}

Bytes encode(const HeightAnswer& m) {
  FlatBufferBuilder fbb(128 + m.samples.size() * sizeof(wire::SurfaceSample));
  const auto samples = fbb.CreateVectorOfStructs(m.samples);
  wire::HeightAnswerBuilder b(fbb);
  b.add_request_id(m.request_id);
  b.add_tick64(m.tick);
  b.add_profile_id(m.profile_id);
  b.add_samples(samples);
  return finish(fbb, wire::Body::HeightAnswer, b.Finish());
}

Bytes encode(const AnyMessage& message) {
  return std::visit([](const auto& m) { return encode(m); }, message);
}

bool fits_datagram(std::span<const std::uint8_t> bytes) { return bytes.size() <= kMaxDatagram; }

}  // namespace ocean::protocol
