#include "server_config.hpp"

#include "cascade_scene.hpp"

#include "config_options.hpp"
#include "profile.hpp"
#include "servable_scene.hpp"
#include "param_message.hpp"
#include "wire_limits.hpp"

#include <spdlog/common.h>

#include <algorithm>
#include <cmath>

namespace ocean::server {
namespace {

// model::validate names SceneParams fields ("wind_speed_mps = ..."); a user typed a flag.
std::string name_scene_flag(const std::string& scene_message) {
  const std::string field = scene_message.substr(0, scene_message.find(' '));
  for (const ConfigOption& option : config_options()) {
    std::string_view fields = option.scene_fields;
    while (!fields.empty()) {
      const std::size_t space = fields.find(' ');
      if (fields.substr(0, space) == field) return "--" + std::string(option.name) + ": " + scene_message;
      fields = space == std::string_view::npos ? std::string_view() : fields.substr(space + 1);
    }
  }
  return "scene: " + scene_message;
}

std::string validate_profiles(const ServerConfig& config) {
  if (config.profiles.empty()) return "--profiles: at least one profile must be offered";
  std::string known;
  for (const Profile& p : all_profiles()) known += (known.empty() ? "" : ", ") + std::string(p.name);
  const int sim_grid = std::min(config.scene.size_x, config.scene.size_z);
  for (std::size_t i = 0; i < config.profiles.size(); ++i) {
    const std::string& name = config.profiles[i];
    const Profile* profile = find_profile(std::string_view(name));
    if (!profile) return "--profiles: unknown profile '" + name + "' (known: " + known + ")";
    if (std::count(config.profiles.begin(), config.profiles.begin() + i, name) > 0)
      return "--profiles: profile '" + name + "' is listed twice";
    if (profile->cascades.empty() && profile->grid > sim_grid)  // cascades realize their own lattices
      return "--profiles: profile '" + name + "' streams a " + std::to_string(profile->grid) + "x" +
             std::to_string(profile->grid) + " grid, larger than the simulation (--size " +
             std::to_string(sim_grid) + "); raise --size or drop the profile";
    for (std::size_t c = 0; c < profile->cascades.size(); ++c) {
      try {
        (void)model::cascade_scene(config.scene, profile->cascades[c], static_cast<int>(c));
      } catch (const model::ParamError& e) {
        return "--profiles: profile '" + name + "' cannot realize its " + e.what() + " with this --patch";
      }
    }
    if (config.tick_rate_hz % profile->rate_hz != 0)
      return "--tick-rate " + std::to_string(config.tick_rate_hz) + ": profile '" + name + "' streams at " +
             std::to_string(profile->rate_hz) + " Hz, so the tick rate must be a multiple of it";
  }
  return {};
}

}  // namespace

namespace {

// The wake's square and every vessel inside it, sailing as model::validate allows.
std::string validate_vessels(const ServerConfig& config) {
  if (!(config.wake_size_m >= 64.0 && config.wake_size_m <= 8192.0))
    return "--wake-size " + model::format_value(config.wake_size_m) + ": must be in [64, 8192] metres";
  if (!(std::fabs(config.wake_origin_x_m) <= 1e6) || !(std::fabs(config.wake_origin_z_m) <= 1e6))
    return "--wake-origin-x/--wake-origin-z: must be within 1e6 metres";
  if (!(config.wake_decay_per_s >= 0.01 && config.wake_decay_per_s <= 10.0))
    return "--wake-decay " + model::format_value(config.wake_decay_per_s) + ": must be in [0.01, 10] per second";
  if (config.vessels.size() > protocol::kMaxVessels)
    return "[[vessel]]: " + std::to_string(config.vessels.size()) + " vessels; at most " + std::to_string(protocol::kMaxVessels);
  for (const model::VesselTrack& v : config.vessels) {
    if (v.points.size() > protocol::kMaxWaypoints)
      return "[[vessel]] " + std::to_string(v.id) + ": " + std::to_string(v.points.size()) + " waypoints; at most " +
             std::to_string(protocol::kMaxWaypoints);
    const std::string table = v.presence == model::Presence{} ? "[[vessel]] " : "[[drop]] ";
    if (std::string error = validate_in_square(v, config.wake_origin_x_m, config.wake_origin_z_m, config.wake_size_m);
        !error.empty())
      return table + error;
    for (const model::VesselTrack& other : config.vessels)
      if (&other != &v && other.id == v.id) return table + std::to_string(v.id) + ": two vessels or objects share this id";
  }
  return {};
}

}  // namespace

model::VesselTrack dropped_object(std::uint32_t id, double size_m, double x_m, double z_m, model::Presence presence) {
  model::VesselTrack object;
  object.id = id;
  object.hull = {size_m, size_m, 0.5 * size_m};
  object.points = {{0.0, x_m, z_m}};
  object.presence = presence;
  return object;
}

std::string validate_in_square(const model::VesselTrack& track, double origin_x_m, double origin_z_m, double size_m) {
  model::TrackLimits limits;
  limits.world_min_m = 0.0;
  limits.world_max_m = size_m;
  model::VesselTrack local = track;
  for (model::Waypoint& p : local.points) {
    p.x_m -= origin_x_m;
    p.z_m -= origin_z_m;
  }
  if (std::string error = model::validate(local, limits); !error.empty())
    return error + " (in the wake's square, corner (" + model::format_value(origin_x_m) + ", " +
           model::format_value(origin_z_m) + "), side " + model::format_value(size_m) + " m)";
  return {};
}

namespace {

// The page, the WebSocket and their TLS go together.
std::string validate_browser_listeners(const ServerConfig& config) {
  if (config.web_listen && !config.stream_address("ws"))
    return "--web-listen serves the browser viewer, which connects over WebSocket: give --ws-listen too";
  if (config.tls_cert.empty() != config.tls_key.empty())
    return config.tls_cert.empty() ? "--tls-key needs --tls-cert (the certificate the key belongs to)"
                                   : "--tls-cert needs --tls-key (the certificate's private key)";
  if (!config.tls_cert.empty() && !config.stream_address("ws"))
    return "--tls-cert secures the browser listeners (--ws-listen, --web-listen): give --ws-listen too";
  return {};
}

}  // namespace

std::string validate_server_config(const ServerConfig& config) {
  if (std::string error = model::validate(config.scene); !error.empty()) return name_scene_flag(error);
  std::string schedule_error;
  const SceneSchedule schedule = make_schedule(config, schedule_error);
  if (schedule_error.empty()) schedule_error = schedule.validate();
  if (!schedule_error.empty()) return "schedule: " + schedule_error;
  if (std::string error = validate_vessels(config); !error.empty()) return error;
  if (config.tick_rate_hz < kMinTickRateHz || config.tick_rate_hz > kMaxTickRateHz)
    return "--tick-rate " + std::to_string(config.tick_rate_hz) + ": must be an integer in " +
           std::to_string(kMinTickRateHz) + ".." + std::to_string(kMaxTickRateHz) + " Hz";
  if (config.udp_public_port < 0 || config.udp_public_port > 65535)
    return "--udp-public-port " + std::to_string(config.udp_public_port) + ": must be in 0..65535 (0 = the bound port)";
  if (config.max_clients < 1 || config.max_clients > kMaxClientsLimit)
    return "--max-clients " + std::to_string(config.max_clients) + ": must be in 1.." +
           std::to_string(kMaxClientsLimit);
  if (config.max_handshakes < 1 || config.max_handshakes > kMaxClientsLimit)
    return "--max-handshakes " + std::to_string(config.max_handshakes) + ": must be in 1.." +
           std::to_string(kMaxClientsLimit);
  if (config.admission_target && !(*config.admission_target > 0.0 && *config.admission_target <= 3.0))
    return "--admission-target " + std::to_string(*config.admission_target) +
           ": must be in (0, 3] (the network thread's running share plus three times its waiting share), or off";
  if (config.max_handshakes_per_ip < 1 || config.max_handshakes_per_ip > config.max_handshakes)
    return "--max-handshakes-per-ip " + std::to_string(config.max_handshakes_per_ip) + ": must be in 1..--max-handshakes (" +
           std::to_string(config.max_handshakes) + ")";
  if (config.max_connections_per_ip < 0 || config.max_connections_per_ip > kMaxClientsLimit)
    return "--max-connections-per-ip " + std::to_string(config.max_connections_per_ip) + ": must be in 0.." +
           std::to_string(kMaxClientsLimit) + " (0 = no limit)";
  if (!(config.connect_rate_per_ip >= 0.0) || config.connect_rate_per_ip > kMaxClientsLimit)
    return "--connect-rate-per-ip " + std::to_string(config.connect_rate_per_ip) + ": must be in 0.." +
           std::to_string(kMaxClientsLimit) + " connections a second (0 = no limit)";
  if (!(config.handshake_timeout_s > 0.0) || config.handshake_timeout_s > 60.0)
    return "--handshake-timeout " + std::to_string(config.handshake_timeout_s) + ": must be in (0, 60] seconds";
  if (config.timeline_lease_s < 2 || config.timeline_lease_s > 300)
    return "--timeline-lease " + std::to_string(config.timeline_lease_s) + ": must be in 2..300 seconds";
  if (config.udp_redundancy < 0 || config.udp_redundancy > kMaxUdpRedundancy)
    return "--udp-redundancy " + std::to_string(config.udp_redundancy) + ": must be in 0.." +
           std::to_string(kMaxUdpRedundancy) + " earlier frames per datagram";
  if (!(config.idle_timeout_s > 0.0) || config.idle_timeout_s > 3600.0)
    return "--idle-timeout " + std::to_string(config.idle_timeout_s) + ": must be in (0, 3600] seconds";
  if (spdlog::level::from_str(config.log_level) == spdlog::level::off && config.log_level != "off")
    return "--log-level '" + config.log_level + "': must be one of trace, debug, info, warn, error, critical, off";
  if (!config.admin_token_file.empty() && config.admin_token.empty())
    return "--admin-token-file '" + config.admin_token_file + "': the token is empty";
  if (std::string error = validate_browser_listeners(config); !error.empty()) return error;
  if (std::string error = validate_profiles(config); !error.empty()) return error;
  // Every scene it will compute, the scheduled ones too, must fit every offered stream.
  std::vector<const Profile*> offered;
  for (const std::string& name : config.profiles) offered.push_back(find_profile(std::string_view(name)));
  if (std::string error = servable_scene(config.scene, offered); !error.empty()) return "the scene: " + error;
  for (std::size_t i = 0; i < schedule.changes().size(); ++i)
    if (std::string error = servable_scene(schedule.changes()[i].scene, offered); !error.empty())
      return "schedule entry " + std::to_string(i + 1) + " (tick " + std::to_string(schedule.changes()[i].tick) +
             "): " + error;
  return {};
}

SceneSchedule make_schedule(const ServerConfig& config, std::string& error) {
  ServerConfig scratch = config;
  std::vector<ScheduledScene> changes;
  for (std::size_t i = 0; i < config.schedule.size(); ++i) {
    const ScheduleEntry& entry = config.schedule[i];
    for (const auto& [name, value] : entry.settings) {
      const ConfigOption* option = find_config_option(name);
      std::string problem = !option || !option->schedulable ? "cannot be scheduled" : option->apply(scratch, value);
      if (!problem.empty() && error.empty())
        error = "schedule entry " + std::to_string(i + 1) + " (tick " + std::to_string(entry.tick) + "): " + name +
                " " + problem;
    }
    changes.push_back({entry.tick, scratch.scene});
  }
  return SceneSchedule(config.scene, std::move(changes));
}

}  // namespace ocean::server
