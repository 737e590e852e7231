// Plain C++ values of every message in ocean.fbs, so the server and clients build and read
// messages without touching FlatBuffers. One struct per message; fields, units and limits are
// those of ocean.fbs (PROTOCOL.md lists them); enums are the generated wire enums.
#pragma once

#include "common/cascade.hpp"
#include "common/wake_lattice.hpp"
#include "vessel_track.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene_params.hpp"
#include "tick.hpp"
#include "ocean_generated.h"
#include "wire_reason.hpp"

namespace ocean::protocol {

using Bytes = std::vector<std::uint8_t>;

struct StreamParams {
  std::uint8_t profile_id = 0;
  std::uint16_t grid = 0;
  double patch_x_m = 0.0;
  double patch_z_m = 0.0;
  double gravity_mps2 = 9.81;
  double depth_m = 0.0;  // 0 = deep water
  std::uint16_t rate_hz = 0;
  float height_step_m = 0.0f;
  float slope_step = 0.0f;
  float disp_step_m = 0.0f;
  bool normals = false;
  bool choppy = false;
  std::vector<Cascade> cascades;  // the profile's; empty for one lattice
  WakeLattice wake;  // grid 0: the stream carries no wake (no vessels)
  bool operator==(const StreamParams&) const = default;
};

// The scene as it is (model/scene_params.hpp): the wire's own conventions (deep water 0, the
// schema's enums, 16-bit sizes) are the builders' and readers' business. `band` is not carried.
using SceneParams = model::SceneParams;

struct Hello {
  std::uint8_t profile_id = 0;  // 0 = let the server choose
  std::uint64_t bandwidth_bps = 0;
  wire::Transport transport = wire::Transport::udp;
  std::string client_name;
  bool operator==(const Hello&) const = default;
};

struct Welcome {
  std::uint64_t session_id = 0;
  StreamParams stream;
  SceneParams scene;
  std::vector<std::uint8_t> offered_profiles;
  std::int64_t epoch_unix_ms = 0;
  Tick current_tick = 0;
  double tick_period_s = 0.0;
  std::uint16_t udp_port = 0;
  Bytes udp_cookie;
  std::uint32_t max_message_bytes = 0;
  std::uint32_t scene_serial = 0;  // the serial of `scene`; chunks name it mod 256
  std::vector<model::VesselTrack> vessels;  // forcing the stream's wake lattice (CODEC.md 7.9)
  bool operator==(const Welcome&) const = default;
};

struct UdpHello {  // encode() adds the padding
  std::uint64_t session_id = 0;
  Bytes cookie;
  bool operator==(const UdpHello&) const = default;
};

struct UdpReady {
  std::uint64_t session_id = 0;
  bool operator==(const UdpReady&) const = default;
};

// Frame records for TCP (version 2): the block of frame_records.hpp.
struct FrameData {
  Bytes frames;
  bool operator==(const FrameData&) const = default;
};

struct Ack {
  std::uint64_t session_id = 0;
  Bytes cookie;
  Tick latest_tick = 0;
  std::uint32_t ack_bits = 0;  // bit i = tick latest_tick - 1 - i received
  bool operator==(const Ack&) const = default;
};

struct KeyframeRequest {
  std::uint64_t session_id = 0;
  Bytes cookie;
  wire::KeyframeReason reason = wire::KeyframeReason::startup;
  bool operator==(const KeyframeRequest&) const = default;
};

struct SetTransport {
  wire::Transport transport = wire::Transport::tcp;
  bool operator==(const SetTransport&) const = default;
};

// What an admin does to a vessel (ParamChange.vessel, PROTOCOL.md 8).
struct VesselCommand {
  wire::VesselAction action = wire::VesselAction::none;
  std::uint32_t id = 0;
  model::Hull hull;  // add
  double x_m = 0.0, z_m = 0.0;  // add, drop
  double heading_deg = 0.0, speed_mps = 0.0;  // add, course
  double size_m = 0.0;  // drop
  bool operator==(const VesselCommand&) const = default;
};

struct ParamChange {
  std::string admin_token;
  std::uint32_t request_id = 0;
  std::optional<double> wind_speed_mps;
  std::optional<double> wind_dir_deg;
  std::optional<double> amplitude;
  std::optional<double> choppiness;
  std::optional<wire::Spectrum> spectrum;
  std::optional<VesselCommand> vessel;
  bool operator==(const ParamChange&) const = default;
};

struct SceneUpdate {
  std::uint32_t request_id = 0;
  Tick effective_tick = 0;
  SceneParams scene;
  std::uint32_t serial = 0;  // differs from the previous scene's mod 256 (PROTOCOL.md 6.2); chunks name it mod 256
  std::optional<std::vector<model::VesselTrack>> vessels = std::nullopt;  // the fleet from effective_tick on, when it changes
  bool operator==(const SceneUpdate&) const = default;
};

struct Error {
  Reason code = Reason::internal_error;
  std::string text;
  bool operator==(const Error&) const = default;
};

struct Bye {
  wire::ByeReason reason = wire::ByeReason::unspecified;
  std::string text;
  bool operator==(const Bye&) const = default;
};

struct Ping {
  std::uint64_t session_id = 0;
  Bytes cookie;
  std::uint32_t seq = 0;
  std::uint64_t client_time_us = 0;
  bool operator==(const Ping&) const = default;
};

struct Pong {
  std::uint32_t seq = 0;
  std::uint64_t client_time_us = 0;
  Tick server_tick = 0;
  std::int64_t server_time_unix_ms = 0;
  bool operator==(const Pong&) const = default;
};

// The sea at a batch of world points (version 4, admin only): the server answers each point of
// the stream of profile_id (0: its first offered profile) at its newest tick.
struct HeightQuery {
  std::string admin_token;
  std::uint32_t request_id = 0;
  std::uint8_t profile_id = 0;
  std::vector<wire::QueryPoint> points;
  bool operator==(const HeightQuery& o) const {
    return admin_token == o.admin_token && request_id == o.request_id && profile_id == o.profile_id &&
           std::equal(points.begin(), points.end(), o.points.begin(), o.points.end(), [](const auto& a, const auto& b) {
             return a.x_m() == b.x_m() && a.z_m() == b.z_m();
           });
  }
};

struct HeightAnswer {
  std::uint32_t request_id = 0;
  Tick tick = 0;
  std::uint8_t profile_id = 0;
  std::vector<wire::SurfaceSample> samples;  // one per point of the query, in its order
  bool operator==(const HeightAnswer& o) const {
    return request_id == o.request_id && tick == o.tick && profile_id == o.profile_id &&
           std::equal(samples.begin(), samples.end(), o.samples.begin(), o.samples.end(), [](const auto& a, const auto& b) {
             return a.height_m() == b.height_m() && a.normal_x() == b.normal_x() && a.normal_y() == b.normal_y() &&
                    a.normal_z() == b.normal_z() && a.vertical_velocity_mps() == b.vertical_velocity_mps();
           });
  }
};

// Any one message, as decode() returns it.
// (FrameChunk and FrameBundle are version 1 only: a version-2 peer refuses them.)
using AnyMessage = std::variant<Hello, Welcome, UdpHello, UdpReady, Ack, KeyframeRequest, SetTransport,
                                ParamChange, SceneUpdate, Error, Bye, Ping, Pong, FrameData, HeightQuery,
                                HeightAnswer>;

}  // namespace ocean::protocol
