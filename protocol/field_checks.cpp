// One check function per message body; the rules and their order are those of PROTOCOL.md.
#include "field_checks.hpp"
#include "message_readers.hpp"

#include <bit>
#include <cmath>
#include <type_traits>

#include "common/wake_lattice.hpp"
#include "vessel_track.hpp"
#include "profile.hpp"
#include "scene_params.hpp"
#include "wire_limits.hpp"

namespace ocean::protocol::detail {
namespace {

constexpr Problem kOk{};

Problem fail(Reason reason, std::string_view field, std::string_view rule) {
  return Problem{reason, field, rule};
}

// A finite number inside [lo, hi]; NaN and infinity are told apart from a mere range error.
Problem number(double value, double lo, double hi, std::string_view field, std::string_view rule) {
  if (!std::isfinite(value)) return fail(Reason::non_finite_value, field, "a finite number");
  if (value < lo || value > hi) return fail(Reason::out_of_range, field, rule);
  return kOk;
}

Problem positive(double value, std::string_view field) {
  if (!std::isfinite(value)) return fail(Reason::non_finite_value, field, "a finite number");
  if (!(value > 0.0)) return fail(Reason::out_of_range, field, "> 0");
  return kOk;
}

template <typename Enum>
Problem known_enum(Enum value, std::string_view field) {
  using U = std::underlying_type_t<Enum>;
  if (static_cast<U>(value) > static_cast<U>(Enum::MAX))
    return fail(Reason::bad_enum, field, "a value defined in ocean.fbs");
  return kOk;
}

bool valid_utf8(const flatbuffers::String& text) {
  const auto* p = reinterpret_cast<const unsigned char*>(text.data());
  const auto* end = p + text.size();
  while (p < end) {
    const unsigned char c = *p;
    const int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (extra < 0 || end - p <= extra) return false;
    char32_t code = extra == 0 ? c : c & (0x3F >> extra);
    for (int i = 1; i <= extra; ++i) {
      if ((p[i] & 0xC0) != 0x80) return false;
      code = (code << 6) | (p[i] & 0x3F);
    }
    constexpr char32_t kMinOfLength[] = {0, 0x80, 0x800, 0x10000};
    if (code < kMinOfLength[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
      return false;
    p += extra + 1;
  }
  return true;
}

Problem text(const flatbuffers::String* value, std::size_t max_bytes, std::string_view field,
             std::string_view rule) {
  if (!value) return kOk;
  if (value->size() > max_bytes || !valid_utf8(*value)) return fail(Reason::bad_string, field, rule);
  return kOk;
}

Problem session(std::uint64_t id, std::string_view field) {
  return id == 0 ? fail(Reason::bad_session, field, "a session id from Welcome, never 0") : kOk;
}

// On UDP a client proves itself with the cookie, so it must be there; on TCP it may be absent.
Problem cookie(const flatbuffers::Vector<std::uint8_t>* value, bool required, std::string_view field) {
  const std::size_t size = value ? value->size() : 0;
  if (size == 0 && !required) return kOk;
  if (size < kMinCookieBytes || size > kMaxCookieBytes)
    return fail(Reason::bad_cookie, field, "8..64 bytes, required on UDP");
  return kOk;
}

// The scene's physical ranges, shared by SceneParams, StreamParams and ParamChange.
Problem patch(double v, std::string_view field) { return number(v, model::kMinPatchM, model::kMaxPatchM, field, "in [0.01, 1e6] m"); }
Problem gravity(double v, std::string_view field) {
  return number(v, model::kMinGravityMps2, model::kMaxGravityMps2, field, "in [0.01, 1000] m/s^2");
}
Problem depth(double v, std::string_view field) { return number(v, 0, HUGE_VAL, field, ">= 0 m (0 = deep water)"); }
Problem wind_speed(double v, std::string_view field) { return number(v, 0, model::kMaxWindSpeedMps, field, "in [0, 100] m/s"); }
Problem wind_dir(double v, std::string_view field) {
  return number(v, -model::kMaxWindDirDeg, model::kMaxWindDirDeg, field, "in [-1e6, 1e6] degrees");
}
Problem amplitude(double v, std::string_view field) { return number(v, 0, model::kMaxAmplitude, field, "in [0, 1e6]"); }
Problem choppiness(double v, std::string_view field) { return number(v, 0, model::kMaxChoppiness, field, "in [0, 100]"); }

Problem check_scene(const wire::SceneParams& s) {
  auto power_of_two = [](std::uint16_t n) {
    return n >= model::kMinSceneSize && n <= model::kMaxSceneSize && std::has_single_bit(n);
  };
  if (!power_of_two(s.size_x())) return fail(Reason::bad_dimensions, "SceneParams.size_x", "a power of two in [16, 2048]");
  if (!power_of_two(s.size_z())) return fail(Reason::bad_dimensions, "SceneParams.size_z", "a power of two in [16, 2048]");
  if (auto p = patch(s.patch_x_m(), "SceneParams.patch_x_m")) return p;
  if (auto p = patch(s.patch_z_m(), "SceneParams.patch_z_m")) return p;
  if (auto p = known_enum(s.spectrum(), "SceneParams.spectrum")) return p;
  if (auto p = known_enum(s.spreading(), "SceneParams.spreading")) return p;
  if (auto p = wind_speed(s.wind_speed_mps(), "SceneParams.wind_speed_mps")) return p;
  if (auto p = wind_dir(s.wind_dir_deg(), "SceneParams.wind_dir_deg")) return p;
  if (auto p = number(s.fetch_m(), model::kMinFetchM, model::kMaxFetchM, "SceneParams.fetch_m", "in [1, 1e8] m")) return p;
  if (auto p = amplitude(s.amplitude(), "SceneParams.amplitude")) return p;
  if (auto p = depth(s.depth_m(), "SceneParams.depth_m")) return p;
  if (auto p = number(s.small_wave_m(), 0, model::kMaxSmallWaveM, "SceneParams.small_wave_m", "in [0, 1e6] m")) return p;
  if (auto p = choppiness(s.choppiness(), "SceneParams.choppiness")) return p;
  return gravity(s.gravity_mps2(), "SceneParams.gravity_mps2");
}

Problem check_stream(const wire::StreamParams& s) {
  const Profile* profile = find_profile(s.profile_id());
  if (!profile) return fail(Reason::unknown_profile, "StreamParams.profile_id", "an id in protocol/profile.hpp");
  if (s.grid() != profile->grid) return fail(Reason::bad_dimensions, "StreamParams.grid", "the profile's grid");
  if (s.normals() != profile->normals) return fail(Reason::bad_dimensions, "StreamParams.normals", "the profile's flag");
  if (s.choppy() != profile->choppy) return fail(Reason::bad_dimensions, "StreamParams.choppy", "the profile's flag");
  const std::size_t cascades = s.cascades() ? s.cascades()->size() : 0;
  bool same = cascades == profile->cascades.size();
  for (std::size_t i = 0; same && i < cascades; ++i) {
    const wire::Cascade* c = s.cascades()->Get(static_cast<flatbuffers::uoffset_t>(i));
    same = Cascade{c->patch_scale(), c->grid(), {c->band_min(), c->band_max()}} == profile->cascades[i];
  }
  if (!same) return fail(Reason::bad_dimensions, "StreamParams.cascades", "the profile's cascades");
  if (const wire::WakeLattice* w = s.wake()) {
    const WakeLattice wake{w->grid(),        w->size_m(),         w->origin_x_m(), w->origin_z_m(),
                           w->decay_per_s(), w->viscosity_m2ps(), w->epoch_ticks()};
    if (const char* problem = wake_problem(wake)) return fail(Reason::out_of_range, "StreamParams.wake", problem);
  }
  if (auto p = patch(s.patch_x_m(), "StreamParams.patch_x_m")) return p;
  if (auto p = patch(s.patch_z_m(), "StreamParams.patch_z_m")) return p;
  if (auto p = gravity(s.gravity_mps2(), "StreamParams.gravity_mps2")) return p;
  if (auto p = depth(s.depth_m(), "StreamParams.depth_m")) return p;
  if (s.rate_hz() < 1 || s.rate_hz() > kMaxRateHz) return fail(Reason::out_of_range, "StreamParams.rate_hz", "in [1, 240]");
  if (auto p = positive(s.height_step_m(), "StreamParams.height_step_m")) return p;
  if (auto p = positive(s.slope_step(), "StreamParams.slope_step")) return p;
  return positive(s.disp_step_m(), "StreamParams.disp_step_m");
}

Problem check(const wire::Hello& m, const wire::Message&, std::size_t, wire::Transport) {
  if (m.profile_id() != 0 && !find_profile(m.profile_id()))
    return fail(Reason::unknown_profile, "Hello.profile_id", "0 or an id in protocol/profile.hpp");
  if (auto p = known_enum(m.transport(), "Hello.transport")) return p;
  return text(m.client_name(), kMaxClientNameBytes, "Hello.client_name", "UTF-8, at most 64 bytes");
}

Problem check_vessels(const wire::Welcome& m);

Problem check(const wire::Welcome& m, const wire::Message&, std::size_t, wire::Transport) {
  if (auto p = session(m.session_id(), "Welcome.session_id")) return p;
  if (!m.stream()) return fail(Reason::missing_field, "Welcome.stream", "present");
  if (!m.scene()) return fail(Reason::missing_field, "Welcome.scene", "present");
  if (auto p = check_stream(*m.stream())) return p;
  if (auto p = check_scene(*m.scene())) return p;
  // A cascade realizes its own lattice; only a stream of one is cut from the scene's grid.
  if (!m.stream()->cascades() && (m.stream()->grid() > m.scene()->size_x() || m.stream()->grid() > m.scene()->size_z()))
    return fail(Reason::bad_dimensions, "StreamParams.grid", "<= SceneParams.size_x and size_z");
  const auto* offered = m.offered_profiles();
  if (!offered || offered->size() == 0 || offered->size() > kMaxOfferedProfiles)
    return fail(Reason::bad_dimensions, "Welcome.offered_profiles", "1..16 profile ids");
  bool stream_offered = false;
  for (std::uint8_t id : *offered) {
    if (!find_profile(id)) return fail(Reason::unknown_profile, "Welcome.offered_profiles", "ids in protocol/profile.hpp");
    stream_offered = stream_offered || id == m.stream()->profile_id();
  }
  if (!stream_offered) return fail(Reason::unknown_profile, "StreamParams.profile_id", "one of Welcome.offered_profiles");
  if (m.epoch_unix_ms() < 0) return fail(Reason::out_of_range, "Welcome.epoch_unix_ms", ">= 0");
  if (auto p = number(m.tick_period_s(), 1e-6, kMaxTickPeriodS, "Welcome.tick_period_s", "in (0, 10]")) return p;
  if (auto p = cookie(m.udp_cookie(), m.udp_port() != 0, "Welcome.udp_cookie")) return p;
  if (m.udp_port() == 0 && m.udp_cookie() && m.udp_cookie()->size() != 0)
    return fail(Reason::bad_cookie, "Welcome.udp_cookie", "empty when udp_port is 0");
  if (m.max_message_bytes() < kMinMaxMessageBytes || m.max_message_bytes() > kMaxMaxMessageBytes)
    return fail(Reason::out_of_range, "Welcome.max_message_bytes", "in [1200, 4194304]");
  return check_vessels(m);
}

// Each vessel a track model::validate accepts in a world of +-1e7 m (PROTOCOL.md 8), at most 32.
Problem check_fleet(const flatbuffers::Vector<flatbuffers::Offset<wire::Vessel>>& vessels, const char* field) {
  if (vessels.size() > kMaxVessels) return fail(Reason::bad_dimensions, field, "at most 32 vessels");
  model::TrackLimits limits;
  limits.world_min_m = -1e7;
  limits.world_max_m = 1e7;
  for (const wire::Vessel* v : vessels) {
    if (!v->waypoints() || v->waypoints()->size() == 0 || v->waypoints()->size() > kMaxWaypoints)
      return fail(Reason::bad_dimensions, "Vessel.waypoints", "1..64 waypoints");
    if (!model::validate(protocol::read(*v), limits).empty())
      return fail(Reason::out_of_range, field,
                  "hulls (0, 400] m long, beam (0, length], draft (0, 25] m; waypoints within 1e7 m, times from 0 "
                  "increasing, legs at most 20 m/s, a repeating track closed; presence from -inf (then for good) or "
                  "within 1e12 s, for (0, 1e12] s or inf, every 0 or (0, 1e12] s and no shorter than it lasts");
  }
  return kOk;
}

// The Welcome's vessels only beside a wake lattice they can force.
Problem check_vessels(const wire::Welcome& m) {
  if (!m.vessels() || m.vessels()->size() == 0) return kOk;
  if (!m.stream()->wake()) return fail(Reason::bad_dimensions, "Welcome.vessels", "absent without StreamParams.wake");
  return check_fleet(*m.vessels(), "Welcome.vessels");
}

// Numbers a vessel command may carry: finite (their ranges are the server's to check, with a
// reason naming the limit).
Problem check_vessel_command(const wire::VesselCommand& v) {
  if (v.action() == wire::VesselAction::none) return fail(Reason::missing_field, "VesselCommand.action", "add, course, remove or drop");
  if (auto p = known_enum(v.action(), "VesselCommand.action")) return p;
  for (const double x : {v.length_m(), v.beam_m(), v.draft_m(), v.x_m(), v.z_m(), v.heading_deg(), v.speed_mps(), v.size_m()})
    if (!std::isfinite(x)) return fail(Reason::non_finite_value, "VesselCommand", "finite numbers");
  return kOk;
}

Problem check(const wire::UdpHello& m, const wire::Message&, std::size_t size, wire::Transport) {
  if (auto p = session(m.session_id(), "UdpHello.session_id")) return p;
  if (auto p = cookie(m.cookie(), true, "UdpHello.cookie")) return p;
  if (size < kUdpHelloMinBytes) return fail(Reason::unpadded_udp_hello, "UdpHello.padding", "message >= 256 bytes");
  return kOk;
}

Problem check(const wire::UdpReady& m, const wire::Message&, std::size_t, wire::Transport) {
  return session(m.session_id(), "UdpReady.session_id");
}

// The block's own structure is checked where it is parsed (decode_frame_block); here only that
// there is one.
Problem check(const wire::FrameData& m, const wire::Message&, std::size_t, wire::Transport) {
  if (!m.frames() || m.frames()->size() == 0) return fail(Reason::missing_field, "FrameData.frames", "a non-empty block");
  return kOk;
}

Problem check(const wire::Ack& m, const wire::Message&, std::size_t, wire::Transport transport) {
  if (auto p = session(m.session_id(), "Ack.session_id")) return p;
  return cookie(m.cookie(), transport == wire::Transport::udp, "Ack.cookie");
}

Problem check(const wire::KeyframeRequest& m, const wire::Message&, std::size_t, wire::Transport transport) {
  if (auto p = session(m.session_id(), "KeyframeRequest.session_id")) return p;
  if (auto p = cookie(m.cookie(), transport == wire::Transport::udp, "KeyframeRequest.cookie")) return p;
  return known_enum(m.reason(), "KeyframeRequest.reason");
}

Problem check(const wire::SetTransport& m, const wire::Message&, std::size_t, wire::Transport) {
  return known_enum(m.transport(), "SetTransport.transport");
}

Problem check(const wire::ParamChange& m, const wire::Message&, std::size_t, wire::Transport) {
  if (!m.admin_token() || m.admin_token()->size() == 0) return fail(Reason::missing_field, "ParamChange.admin_token", "present");
  if (auto p = text(m.admin_token(), kMaxAdminTokenBytes, "ParamChange.admin_token", "UTF-8, at most 128 bytes")) return p;
  if (!m.wind_speed_mps() && !m.wind_dir_deg() && !m.amplitude() && !m.choppiness() && !m.spectrum() && !m.vessel())
    return fail(Reason::missing_field, "ParamChange", "at least one parameter to change, or a vessel command");
  if (m.vessel())
    if (auto p = check_vessel_command(*m.vessel())) return p;
  if (auto v = m.wind_speed_mps())
    if (auto p = wind_speed(*v, "ParamChange.wind_speed_mps")) return p;
  if (auto v = m.wind_dir_deg())
    if (auto p = wind_dir(*v, "ParamChange.wind_dir_deg")) return p;
  if (auto v = m.amplitude())
    if (auto p = amplitude(*v, "ParamChange.amplitude")) return p;
  if (auto v = m.choppiness())
    if (auto p = choppiness(*v, "ParamChange.choppiness")) return p;
  if (auto v = m.spectrum())
    if (auto p = known_enum(*v, "ParamChange.spectrum")) return p;
  return kOk;
}

Problem check(const wire::HeightQuery& m, const wire::Message&, std::size_t, wire::Transport) {
  if (!m.admin_token() || m.admin_token()->size() == 0) return fail(Reason::missing_field, "HeightQuery.admin_token", "present");
  if (auto p = text(m.admin_token(), kMaxAdminTokenBytes, "HeightQuery.admin_token", "UTF-8, at most 128 bytes")) return p;
  if (!m.points() || m.points()->size() == 0) return fail(Reason::missing_field, "HeightQuery.points", "at least one point");
  if (m.points()->size() > kMaxQueryPoints) return fail(Reason::oversized, "HeightQuery.points", "at most 2048 points");
  for (const wire::QueryPoint* p : *m.points())
    if (!std::isfinite(p->x_m()) || !std::isfinite(p->z_m()))
      return fail(Reason::non_finite_value, "HeightQuery.points", "finite coordinates");
  return kOk;
}

Problem check(const wire::HeightAnswer& m, const wire::Message&, std::size_t, wire::Transport) {
  if (m.samples() && m.samples()->size() > kMaxQueryPoints) return fail(Reason::oversized, "HeightAnswer.samples", "at most 2048 samples");
  return kOk;
}

Problem check(const wire::SceneUpdate& m, const wire::Message&, std::size_t, wire::Transport) {
  if (!m.scene()) return fail(Reason::missing_field, "SceneUpdate.scene", "present");
  if (m.vessels())
    if (auto p = check_fleet(*m.vessels(), "SceneUpdate.vessels")) return p;
  return check_scene(*m.scene());
}

Problem check(const wire::Error& m, const wire::Message&, std::size_t, wire::Transport) {
  if (auto p = known_enum(m.code(), "Error.code")) return p;
  return text(m.text(), kMaxTextBytes, "Error.text", "UTF-8, at most 256 bytes");
}

Problem check(const wire::Bye& m, const wire::Message&, std::size_t, wire::Transport) {
  if (auto p = known_enum(m.reason(), "Bye.reason")) return p;
  return text(m.text(), kMaxTextBytes, "Bye.text", "UTF-8, at most 256 bytes");
}

Problem check(const wire::Ping& m, const wire::Message&, std::size_t, wire::Transport transport) {
  if (auto p = session(m.session_id(), "Ping.session_id")) return p;
  return cookie(m.cookie(), transport == wire::Transport::udp, "Ping.cookie");
}

Problem check(const wire::Pong&, const wire::Message&, std::size_t, wire::Transport) { return kOk; }

template <typename Body>
Problem check_as(const wire::Message& message, std::size_t size, wire::Transport transport) {
  const auto* body = message.body_as<Body>();
  if (!body) return fail(Reason::missing_field, "Message.body", "present when body_type is set");
  return check(*body, message, size, transport);
}

}  // namespace

Problem check_body(const wire::Message& message, std::size_t size, wire::Transport transport) {
  switch (message.body_type()) {
    case wire::Body::Hello: return check_as<wire::Hello>(message, size, transport);
    case wire::Body::Welcome: return check_as<wire::Welcome>(message, size, transport);
    case wire::Body::UdpHello: return check_as<wire::UdpHello>(message, size, transport);
    case wire::Body::UdpReady: return check_as<wire::UdpReady>(message, size, transport);
    case wire::Body::FrameChunk:
    case wire::Body::FrameBundle:
      return fail(Reason::unexpected_message, "Message.body_type", "not FrameChunk or FrameBundle (version 1 only)");
    case wire::Body::Ack: return check_as<wire::Ack>(message, size, transport);
    case wire::Body::KeyframeRequest: return check_as<wire::KeyframeRequest>(message, size, transport);
    case wire::Body::SetTransport: return check_as<wire::SetTransport>(message, size, transport);
    case wire::Body::ParamChange: return check_as<wire::ParamChange>(message, size, transport);
    case wire::Body::SceneUpdate: return check_as<wire::SceneUpdate>(message, size, transport);
    case wire::Body::Error: return check_as<wire::Error>(message, size, transport);
    case wire::Body::Bye: return check_as<wire::Bye>(message, size, transport);
    case wire::Body::Ping: return check_as<wire::Ping>(message, size, transport);
    case wire::Body::Pong: return check_as<wire::Pong>(message, size, transport);
    case wire::Body::FrameData: return check_as<wire::FrameData>(message, size, transport);
    case wire::Body::HeightQuery: return check_as<wire::HeightQuery>(message, size, transport);
    case wire::Body::HeightAnswer: return check_as<wire::HeightAnswer>(message, size, transport);
    case wire::Body::NONE: break;
  }
  return fail(Reason::unknown_message_type, "Message.body_type", "a type defined in ocean.fbs");
}

}  // namespace ocean::protocol::detail
