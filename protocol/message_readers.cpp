// Copies verified FlatBuffers tables into plain values; absent vectors and strings read as empty.
#include "message_readers.hpp"

namespace ocean::protocol {
namespace {

Bytes bytes_of(const flatbuffers::Vector<std::uint8_t>* vector) {
  return vector ? Bytes(vector->begin(), vector->end()) : Bytes{};
}

std::string string_of(const flatbuffers::String* text) { return text ? text->str() : std::string{}; }

template <typename T>
std::optional<T> optional_of(flatbuffers::Optional<T> value) {
  return value ? std::optional<T>(*value) : std::nullopt;
}

}  // namespace

StreamParams read(const wire::StreamParams& s) {
  StreamParams out;
  out.profile_id = s.profile_id();
  out.grid = s.grid();
  out.patch_x_m = s.patch_x_m();
  out.patch_z_m = s.patch_z_m();
  out.gravity_mps2 = s.gravity_mps2();
  out.depth_m = s.depth_m();  // the codec's convention too: 0 = deep
  out.rate_hz = s.rate_hz();
  out.height_step_m = s.height_step_m();
  out.slope_step = s.slope_step();
  out.disp_step_m = s.disp_step_m();
  out.normals = s.normals();
  out.choppy = s.choppy();
  if (s.cascades())
    for (const wire::Cascade* c : *s.cascades())
      out.cascades.push_back({c->patch_scale(), c->grid(), {c->band_min(), c->band_max()}});
  if (const wire::WakeLattice* w = s.wake())
    out.wake = {w->grid(),        w->size_m(),         w->origin_x_m(), w->origin_z_m(),
                w->decay_per_s(), w->viscosity_m2ps(), w->epoch_ticks()};
  return out;
}

SceneParams read(const wire::SceneParams& s) {
  SceneParams out;
  out.size_x = s.size_x();
  out.size_z = s.size_z();
  out.patch_x_m = s.patch_x_m();
  out.patch_z_m = s.patch_z_m();
  out.spectrum = static_cast<model::SpectrumKind>(s.spectrum());
  out.spreading = static_cast<model::SpreadingKind>(s.spreading());
  out.wind_speed_mps = s.wind_speed_mps();
  out.wind_dir_deg = s.wind_dir_deg();
  out.fetch_m = s.fetch_m();
  out.amplitude = s.amplitude();
  out.depth_m = model::scene_depth(s.depth_m());
  out.small_wave_m = s.small_wave_m();
  out.choppiness = s.choppiness();
  out.gravity_mps2 = s.gravity_mps2();
  out.seed = s.seed();
  return out;
}

Hello read(const wire::Hello& m) {
  return Hello{m.profile_id(), m.bandwidth_bps(), m.transport(), string_of(m.client_name())};
}

Welcome read(const wire::Welcome& m) {
  Welcome out;
  out.session_id = m.session_id();
  if (m.stream()) out.stream = read(*m.stream());
  if (m.scene()) out.scene = read(*m.scene());
  out.offered_profiles = bytes_of(m.offered_profiles());
  out.epoch_unix_ms = m.epoch_unix_ms();
  out.current_tick = m.current_tick64();
  out.tick_period_s = m.tick_period_s();
  out.udp_port = m.udp_port();
  out.udp_cookie = bytes_of(m.udp_cookie());
  out.max_message_bytes = m.max_message_bytes();
  out.scene_serial = m.scene_serial();
  if (m.vessels())
    for (const wire::Vessel* v : *m.vessels()) out.vessels.push_back(read(*v));
  return out;
}

model::VesselTrack read(const wire::Vessel& v) {
  model::VesselTrack track;
  track.id = v.id();
  track.hull = {v.length_m(), v.beam_m(), v.draft_m()};
  track.repeat = v.repeat();
  if (v.waypoints())
    for (const wire::Waypoint* p : *v.waypoints()) track.points.push_back({p->t_s(), p->x_m(), p->z_m()});
  track.presence = {v.present_from_s(), v.present_for_s(), v.present_every_s()};
  return track;
}

UdpHello read(const wire::UdpHello& m) { return UdpHello{m.session_id(), bytes_of(m.cookie())}; }

UdpReady read(const wire::UdpReady& m) { return UdpReady{m.session_id()}; }

FrameData read(const wire::FrameData& m) { return FrameData{bytes_of(m.frames())}; }

Ack read(const wire::Ack& m) {
  return Ack{m.session_id(), bytes_of(m.cookie()), m.latest_tick64(), m.ack_bits()};
}

KeyframeRequest read(const wire::KeyframeRequest& m) {
  return KeyframeRequest{m.session_id(), bytes_of(m.cookie()), m.reason()};
}

SetTransport read(const wire::SetTransport& m) { return SetTransport{m.transport()}; }

ParamChange read(const wire::ParamChange& m) {
  ParamChange out;
  out.admin_token = string_of(m.admin_token());
  out.request_id = m.request_id();
  out.wind_speed_mps = optional_of(m.wind_speed_mps());
  out.wind_dir_deg = optional_of(m.wind_dir_deg());
  out.amplitude = optional_of(m.amplitude());
  out.choppiness = optional_of(m.choppiness());
  out.spectrum = optional_of(m.spectrum());
  if (const wire::VesselCommand* v = m.vessel())
    out.vessel = VesselCommand{v->action(), v->id(), {v->length_m(), v->beam_m(), v->draft_m()}, v->x_m(), v->z_m(),
                               v->heading_deg(), v->speed_mps(), v->size_m()};
  return out;
}

SceneUpdate read(const wire::SceneUpdate& m) {
  SceneUpdate out;
  out.request_id = m.request_id();
  out.effective_tick = m.effective_tick64();
  if (m.scene()) out.scene = read(*m.scene());
  out.serial = m.serial();
  if (m.vessels()) {
    out.vessels.emplace();
    for (const wire::Vessel* v : *m.vessels()) out.vessels->push_back(read(*v));
  }
  return out;
}

Error read(const wire::Error& m) { return Error{from_wire(m.code()), string_of(m.text())}; }

Bye read(const wire::Bye& m) { return Bye{m.reason(), string_of(m.text())}; }

Ping read(const wire::Ping& m) {
  return Ping{m.session_id(), bytes_of(m.cookie()), m.seq(), m.client_time_us()};
}

Pong read(const wire::Pong& m) {
  return Pong{m.seq(), m.client_time_us(), m.server_tick64(), m.server_time_unix_ms()};
}

HeightQuery read(const wire::HeightQuery& m) {
  HeightQuery out{string_of(m.admin_token()), m.request_id(), m.profile_id(), {}};
  if (m.points())
    for (const wire::QueryPoint* p : *m.points()) out.points.push_back(*p);
  return out;
}

HeightAnswer read(const wire::HeightAnswer& m) {
  HeightAnswer out{m.request_id(), m.tick64(), m.profile_id(), {}};
  if (m.samples())
    for (const wire::SurfaceSample* s : *m.samples()) out.samples.push_back(*s);
  return out;
}

AnyMessage decode(const wire::Message& message) {
  switch (message.body_type()) {
    case wire::Body::Hello: return read(*message.body_as_Hello());
    case wire::Body::Welcome: return read(*message.body_as_Welcome());
    case wire::Body::UdpHello: return read(*message.body_as_UdpHello());
    case wire::Body::UdpReady: return read(*message.body_as_UdpReady());
    case wire::Body::Ack: return read(*message.body_as_Ack());
    case wire::Body::KeyframeRequest: return read(*message.body_as_KeyframeRequest());
    case wire::Body::SetTransport: return read(*message.body_as_SetTransport());
    case wire::Body::ParamChange: return read(*message.body_as_ParamChange());
    case wire::Body::SceneUpdate: return read(*message.body_as_SceneUpdate());
    case wire::Body::Error: return read(*message.body_as_Error());
    case wire::Body::Bye: return read(*message.body_as_Bye());
    case wire::Body::Ping: return read(*message.body_as_Ping());
    case wire::Body::Pong: return read(*message.body_as_Pong());
    case wire::Body::FrameData: return read(*message.body_as_FrameData());
    case wire::Body::HeightQuery: return read(*message.body_as_HeightQuery());
    case wire::Body::HeightAnswer: return read(*message.body_as_HeightAnswer());
    case wire::Body::FrameChunk:   // version 1 only: verification refuses them
    case wire::Body::FrameBundle:
    case wire::Body::NONE: break;
  }
  // verify_message() rejects NONE and unknown types, so this is a caller bug.
  return Error{Reason::unknown_message_type, "decode() called on an unverified message"};
}

}  // namespace ocean::protocol
