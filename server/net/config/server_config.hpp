// ServerConfig: everything ocean-server is told at startup, after flags and the config file are
// merged. Loading (config_loader) fills it; validate_server_config() is the one gate it passes.
#pragma once

#include "listen_address.hpp"
#include "scene_params.hpp"
#include "scene_schedule.hpp"
#include "vessel_track.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ocean::server {

// One [[schedule]] entry as written: from `tick` on, these options (schedulable ones, by name,
// values as text) change. Kept as text so flags that override the base scene also reach later
// entries; make_schedule() turns the list into whole scenes.
struct ScheduleEntry {
  std::int64_t tick = 0;
  std::vector<std::pair<std::string, std::string>> settings;
};

inline constexpr std::int64_t kDefaultEpochUnixMs = 1'767'225'600'000;  // 2026-01-01T00:00:00Z
// The simulation refuses times beyond this (sim::Ocean's limit); the server checks at startup.
inline constexpr double kMaxSimTimeS = 1e9;

struct ServerConfig {
  ListenAddress listen{"0.0.0.0", 7700};         // TCP
  std::optional<ListenAddress> udp_listen;       // empty = the TCP address and (bound) port
  // The UDP port the Welcome names, where clients reach the server through a port mapping that
  // changes it (podman -p 17700:7700/udp, a Service's port); 0 = the bound UDP port.
  int udp_public_port = 0;
  std::optional<ListenAddress> metrics_listen = ListenAddress{"127.0.0.1", 9464};  // empty = off
  // The optional stream transports' addresses (kStreamTransports, config/stream_transports.hpp:
  // "ws" by --ws-listen), by transport name; one absent is off. One map rather than a field each,
  // so that a new transport's row is all the configuration needs.
  std::map<std::string, ListenAddress, std::less<>> stream_listen;
  const ListenAddress* stream_address(std::string_view transport) const {
    const auto found = stream_listen.find(transport);
    return found == stream_listen.end() ? nullptr : &found->second;
  }
  // WebSocket clients (browsers, "ws"): a browser's handshake names the page's Origin; only these
  // are let in ("*": any). Clients that send no Origin always are.
  std::vector<std::string> ws_origins;
  // The browser viewer's page, served over HTTP (off unless given); it connects to the "ws" transport,
  // whose Origin check then also lets in this page as the browser names it. web_root empty: the
  // build tree's web/ or the installed share/ocean/web.
  std::optional<ListenAddress> web_listen;
  std::string web_root;
  // PEM certificate chain and private key: the page (--web-listen) is https and the WebSocket
  // (--ws-listen) wss. Both or neither; read again on SIGHUP.
  std::string tls_cert, tls_key;

  model::SceneParams scene;                         // the scene at the epoch (tick 0 onward)
  std::vector<ScheduleEntry> schedule;            // later scene changes, by tick

  // Vessels ([[vessel]] tables of the config file, world metres) and the square of the world their
  // wakes are simulated on and streamed over (CODEC.md 7.9): none, no wake lattice in any stream.
  std::vector<model::VesselTrack> vessels;
  double wake_size_m = 512.0;
  double wake_origin_x_m = -256.0, wake_origin_z_m = -256.0;
  double wake_decay_per_s = 0.05;
  // --wake on: streams carry the wake lattice even with no vessel in the config, so that
  // ocean-admin can put vessels on an empty sea (auto: only when the config has some).
  bool wake_always = false;
  bool has_wake() const { return wake_always || !vessels.empty(); }

  int tick_rate_hz = 30;
  // Wall-clock time of tick 0: 2026-01-01T00:00:00Z. Not the Unix epoch: the simulation accepts
  // |t| <= 1e9 s (about 31 years), and t = (now - epoch) would already exceed that.
  std::int64_t epoch_unix_ms = kDefaultEpochUnixMs;
  std::vector<std::string> profiles{"mobile", "desktop"};  // names from protocol/profile.hpp

  int max_clients = 64;                           // welcomed sessions (viewer slots)
  // The network thread's load (running + 3 x waiting for a CPU) beyond which new clients are
  // refused (AdmissionBudget); none: only max_clients.
  std::optional<double> admission_target = 0.85;  // AdmissionBudget::kDefaultTarget
  // Connections before their Hello (they never hold a viewer slot): all of them, per address, and
  // how long one may stay silent.
  int max_handshakes = 256;
  int max_handshakes_per_ip = 32;
  // 64: one address cannot hold every viewer slot (300 WebSocket sessions from one did, with no
  // limit); behind a carrier NAT or a proxy that many viewers may share one, so raise it there.
  int max_connections_per_ip = 64;
  // New connections per second from one address range (an IPv4 /24, an IPv6 /64), a burst of
  // twice that; beyond it a connection is closed at accept (ConnectRate). 0 = no limit.
  double connect_rate_per_ip = 50.0;
  double handshake_timeout_s = 3.0;
  int udp_redundancy = 2;                         // earlier unacked frames copied into each datagram
  std::string admin_token_file;                   // empty = admin interface disabled
  std::string admin_token;                        // read from admin_token_file; never logged
  std::vector<std::uint8_t> cookie_key;           // empty = a random key per process
  // The fleet's timeline (etcd://HOST:PORT/PREFIX, issue 37): admin changes go through its log and
  // every replica following it applies them at the same ticks. Empty = this server's alone.
  std::string timeline;
  int timeline_lease_s = 10;  // etcd's lease TTL: store outages shorter than it change nothing
  double idle_timeout_s = 10.0;
  std::string log_level = "info";
};

// Limits enforced by validate_server_config; the help text quotes them.
inline constexpr int kMinTickRateHz = 1;
inline constexpr int kMaxTickRateHz = 240;
inline constexpr int kMaxClientsLimit = 100000;
inline constexpr int kMaxUdpRedundancy = 7;  // a FrameBundle holds at most 8 chunks

// A dropped object as the wake sees it, from a config's [[drop]] or an admin's drop alike: a round
// hull `size_m` across (at most kMaxDropSizeM) pressing half its size deep at (x_m, z_m) while present.
inline constexpr double kMaxDropSizeM = 50.0;
model::VesselTrack dropped_object(std::uint32_t id, double size_m, double x_m, double z_m, model::Presence presence);
// Empty when `track` is a valid track inside the wake's square (corner origin, side size_m: checked
// in the square's own coordinates); else what is wrong, naming the square.
std::string validate_in_square(const model::VesselTrack& track, double origin_x_m, double origin_z_m, double size_m);

// Empty when the configuration is usable; otherwise one message naming the option (as a flag) and
// what is allowed. Checks the scene (model::validate), the schedule, and the server-level options.
std::string validate_server_config(const ServerConfig& config);

// The schedule as the tick loop uses it: the configured scene, then each entry applied on top of
// the previous one. Sets `error` (naming the entry and option) when a value does not apply.
SceneSchedule make_schedule(const ServerConfig& config, std::string& error);

}  // namespace ocean::server
