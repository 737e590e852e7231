#include "config_options.hpp"

#include "epoch.hpp"
#include "option_values.hpp"
#include "profile.hpp"
#include "quoted.hpp"
#include "scene_names.hpp"
#include "stream_listen_options.hpp"
#include "timeline_log.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace ocean::server {
namespace {

// The value names --help shows: "phillips|jonswap" and "cos2s|donelan-banner|hasselmann".
const std::string kSpectrumChoices = model::join_names(model::spectrum_names(), "|", "|");
const std::string kSpreadingChoices = model::join_names(model::spreading_names(), "|", "|");

// --profiles' help names every profile of protocol/profile.hpp, in its order.
std::string profiles_help() {
  std::string names;
  for (const Profile& profile : all_profiles()) names += (names.empty() ? "" : ", ") + std::string(profile.name);
  return "comma-separated stream profiles to offer (" + names + "); each grid <= --size";
}
const std::string kProfilesHelp = profiles_help();

std::string hex_digit_error(std::string_view path) {
  return "file '" + std::string(path) + "' must hold exactly 64 hex digits (a 32-byte key)";
}

// The addresses the server listens on: the primary transport's (TCP), UDP's, the metrics'.
const ConfigOption kNetworkOptions[] = {
    {"listen", "ADDR:PORT", "TCP address to accept clients on; UDP uses it too unless --udp-listen is given (port 0 = any free port)",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       std::string error;
       if (auto a = parse_listen_address(v, error)) c.listen = *a;
       return error;
     },
     [](const ServerConfig& c) { return c.listen.to_string(); }},
    {"udp-listen", "ADDR:PORT", "UDP address for frame datagrams", ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) { return apply_address(c.udp_listen, v, false); },
     [](const ServerConfig& c) { return show_optional_address(c.udp_listen, "the --listen address"); }},
    {"udp-public-port", "N",
     "UDP port clients are told to use, when a port mapping (container, NAT, Service) changes the bound one; "
     "in 0..65535, 0 = the bound port",
     ValueKind::integer, false, [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.udp_public_port); },
     [](const ServerConfig& c) { return c.udp_public_port ? std::to_string(c.udp_public_port) : std::string("the bound port"); }},
    {"metrics-listen", "ADDR:PORT|off", "HTTP address serving /metrics (Prometheus), /healthz and /readyz; 'off' disables it",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) { return apply_address(c.metrics_listen, v, true); },
     [](const ServerConfig& c) { return show_optional_address(c.metrics_listen, "off"); }},
};

// After those, each optional stream transport's listen option (stream_listen_options: --ws-listen),
// then these.
const ConfigOption kOptions[] = {
    {"ws-origins", "LIST",
     "comma-separated page origins (scheme://host[:port]) whose WebSocket handshakes are accepted, or '*' for any; "
     "clients that send no Origin are always accepted",
     ValueKind::text_list, false,
     [](ServerConfig& c, std::string_view v) {
       c.ws_origins = split_list(v);
       for (const std::string& origin : c.ws_origins) {
         const bool web = origin.rfind("http://", 0) == 0 || origin.rfind("https://", 0) == 0;
         if (origin != "*" && (!web || origin.find_first_of(" /", origin.find("://") + 3) != std::string::npos))
           return "origin '" + origin + "' must be scheme://host[:port] (http or https, no path) or '*'";
       }
       return std::string();
     },
     [](const ServerConfig& c) { return c.ws_origins.empty() ? std::string("none") : join(c.ws_origins); }},
    {"web-listen", "ADDR:PORT|off",
     "HTTP address serving the browser viewer's page (needs --ws-listen; its Origin is then let in); 'off' (default) disables it",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) { return apply_address(c.web_listen, v, true); },
     [](const ServerConfig& c) { return show_optional_address(c.web_listen, "off"); }},
    {"web-root", "DIR", "folder holding the browser viewer (index.html, viewer.js, ocean-web.js, ocean-web.wasm)",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       c.web_root = std::string(v);
       return std::string();
     },
     [](const ServerConfig& c) { return c.web_root.empty() ? std::string("the build tree's or installed web viewer") : c.web_root; }},
    {"tls-cert", "FILE", "PEM certificate chain: the page (--web-listen) is then https and the WebSocket wss; read again on SIGHUP",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       c.tls_cert = std::string(v);
       return c.tls_cert.empty() ? std::string("must name a file") : std::string();
     },
     [](const ServerConfig& c) { return c.tls_cert.empty() ? std::string("off") : c.tls_cert; }},
    {"tls-key", "FILE", "PEM private key of --tls-cert", ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       c.tls_key = std::string(v);
       return c.tls_key.empty() ? std::string("must name a file") : std::string();
     },
     [](const ServerConfig& c) { return c.tls_key.empty() ? std::string("off") : c.tls_key; }},
    {"size", "N", "simulation grid N x N samples: a power of two in 16..2048", ValueKind::integer, false,
     [](ServerConfig& c, std::string_view v) {
       int n = 0;
       std::string error = parse_integer(v, n);
       if (error.empty()) c.scene.size_x = c.scene.size_z = n;
       return error;
     },
     [](const ServerConfig& c) { return std::to_string(c.scene.size_x); },
     "size_x size_z"},
    {"patch", "METRES", "side of the square ocean patch the grid covers, in [0.01, 1e6]", ValueKind::number, false,
     [](ServerConfig& c, std::string_view v) {
       double m = 0;
       std::string error = parse_number(v, m);
       if (error.empty()) c.scene.patch_x_m = c.scene.patch_z_m = m;
       return error;
     },
     [](const ServerConfig& c) { return show_number(c.scene.patch_x_m); },
     "patch_x_m patch_z_m"},
    {"spectrum", kSpectrumChoices, "wave spectrum", ValueKind::text, true,
     [](ServerConfig& c, std::string_view v) {
       return apply_name(c.scene.spectrum, v, model::spectrum_from_name, model::spectrum_names);
     },
     [](const ServerConfig& c) { return std::string(model::spectrum_name(c.scene.spectrum)); },
     "spectrum"},
    {"spreading", kSpreadingChoices, "directional spreading (JONSWAP only)", ValueKind::text, true,
     [](ServerConfig& c, std::string_view v) {
       return apply_name(c.scene.spreading, v, model::spreading_from_name, model::spreading_names);
     },
     [](const ServerConfig& c) { return std::string(model::spreading_name(c.scene.spreading)); },
     "spreading"},
    {"wind-speed", "M/S", "wind speed U10 in m/s, in [0, 100]", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.wind_speed_mps); },
     [](const ServerConfig& c) { return show_number(c.scene.wind_speed_mps); },
     "wind_speed_mps"},
    {"wind-dir", "DEG", "direction the wind blows towards, degrees from +x towards +z", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.wind_dir_deg); },
     [](const ServerConfig& c) { return show_number(c.scene.wind_dir_deg); },
     "wind_dir_deg"},
    {"fetch", "METRES", "JONSWAP fetch, in [1, 1e8]", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.fetch_m); },
     [](const ServerConfig& c) { return show_number(c.scene.fetch_m); },
     "fetch_m"},
    {"amplitude", "A", "scale on the spectrum's energy, in [0, 1e6]", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.amplitude); },
     [](const ServerConfig& c) { return show_number(c.scene.amplitude); },
     "amplitude"},
    {"depth", "METRES|deep", "water depth, > 0, or 'deep'", ValueKind::number_or_text, true,
     [](ServerConfig& c, std::string_view v) {
       if (v == "deep") {
         c.scene.depth_m = std::numeric_limits<double>::infinity();
         return std::string();
       }
       std::string error = parse_number(v, c.scene.depth_m);
       return error.empty() ? error : error + " (nor 'deep')";
     },
     [](const ServerConfig& c) {
       return std::isinf(c.scene.depth_m) ? std::string("deep") : show_number(c.scene.depth_m);
     },
     "depth_m"},
    {"choppiness", "LAMBDA", "horizontal displacement scale, in [0, 100] (streamed by choppy profiles)", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.choppiness); },
     [](const ServerConfig& c) { return show_number(c.scene.choppiness); },
     "choppiness"},
    {"small-wave", "METRES", "suppression length of tiny waves, in [0, 1e6] (0 = from the grid spacing)", ValueKind::number, true,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.scene.small_wave_m); },
     [](const ServerConfig& c) { return show_number(c.scene.small_wave_m); },
     "small_wave_m"},
    {"seed", "N", "random seed of the wave phases, unsigned 64-bit: decimal or 0x hex (in TOML a string for seeds >= 2^63)",
     ValueKind::integer_or_text, false, [](ServerConfig& c, std::string_view v) { return parse_seed(v, c.scene.seed); },
     [](const ServerConfig& c) { return std::to_string(c.scene.seed); },
     "seed"},
    {"wake-size", "METRES", "side of the square of the world where vessels sail and their wakes are simulated and streamed "
                            "(CODEC.md 7.9), in [64, 8192]; vessels are [[vessel]] tables of the config file",
     ValueKind::number, false, [](ServerConfig& c, std::string_view v) { return parse_number(v, c.wake_size_m); },
     [](const ServerConfig& c) { return show_number(c.wake_size_m); }},
    {"wake-origin-x", "METRES", "the wake square's corner (smallest x), within 1e6", ValueKind::number, false,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.wake_origin_x_m); },
     [](const ServerConfig& c) { return show_number(c.wake_origin_x_m); }},
    {"wake-origin-z", "METRES", "the wake square's corner (smallest z), within 1e6", ValueKind::number, false,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.wake_origin_z_m); },
     [](const ServerConfig& c) { return show_number(c.wake_origin_z_m); }},
    {"wake-decay", "PER_S", "how fast a wake's waves fade (amplitude e^{-decay t}), in [0.01, 10]", ValueKind::number, false,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.wake_decay_per_s); },
     [](const ServerConfig& c) { return show_number(c.wake_decay_per_s); }},
    {"wake", "auto|on", "auto: streams carry a wake lattice when the config has a [[vessel]] or [[drop]]; on: always, so "
                        "that ocean-admin --vessel can put vessels on an empty sea",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       if (v != "auto" && v != "on") return std::string("must be auto or on, not '") + std::string(v) + "'";
       c.wake_always = v == "on";
       return std::string();
     },
     [](const ServerConfig& c) { return std::string(c.wake_always ? "on" : "auto"); }},
    {"tick-rate", "HZ", "simulation ticks per second, an integer in 1..240 and a multiple of every offered profile's rate",
     ValueKind::integer, false,
     [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.tick_rate_hz); },
     [](const ServerConfig& c) { return std::to_string(c.tick_rate_hz); }},
    {"epoch", "MS|RFC3339", "wall-clock time of tick 0: Unix milliseconds or RFC 3339 (e.g. 2026-11-21T17:00:00Z), within 1e9 s (~31 years) of now; servers sharing it and --tick-rate number ticks alike",
     ValueKind::integer_or_text, false,
     [](ServerConfig& c, std::string_view v) {
       std::string error;
       if (auto ms = parse_epoch_ms(v, error)) c.epoch_unix_ms = *ms;
       return error;
     },
     [](const ServerConfig& c) { return std::to_string(c.epoch_unix_ms); }},
    {"profiles", "LIST", kProfilesHelp, ValueKind::text_list, false,
     [](ServerConfig& c, std::string_view v) {
       c.profiles = split_list(v);
       return std::string();
     },
     [](const ServerConfig& c) { return join(c.profiles); }},
    {"max-clients", "N", "most clients connected at once, in 1..100000", ValueKind::integer, false,
     [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.max_clients); },
     [](const ServerConfig& c) { return std::to_string(c.max_clients); }},
    {"admission-target", "LOAD|off",
     "refuse new clients as server_full once serving more would load the network thread past LOAD (its running "
     "share plus three times its share waiting for a CPU), in (0, 3]; off = only --max-clients",
     ValueKind::number_or_text, false,
     [](ServerConfig& c, std::string_view v) {
       if (v == "off") {
         c.admission_target.reset();
         return std::string();
       }
       double target = 0.0;
       std::string error = parse_number(v, target);
       c.admission_target = target;
       return error.empty() ? error : error + " (nor 'off')";
     },
     [](const ServerConfig& c) {
       return c.admission_target ? show_number(*c.admission_target) : std::string("off");
     }},
    {"max-handshakes", "N",
     "most connections that have not yet sent their Hello, in 1..100000; they never take a --max-clients slot",
     ValueKind::integer, false, [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.max_handshakes); },
     [](const ServerConfig& c) { return std::to_string(c.max_handshakes); }},
    {"max-handshakes-per-ip", "N", "of those, most from one IP address, in 1..--max-handshakes", ValueKind::integer, false,
     [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.max_handshakes_per_ip); },
     [](const ServerConfig& c) { return std::to_string(c.max_handshakes_per_ip); }},
    {"max-connections-per-ip", "N",
     "most connections from one IP address, welcomed or not, in 0..100000 (default 64; 0 = no limit): raise it where "
     "many viewers share an address (a carrier NAT, a proxy, a load test from one host)",
     ValueKind::integer, false, [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.max_connections_per_ip); },
     [](const ServerConfig& c) { return std::to_string(c.max_connections_per_ip); }},
    {"connect-rate-per-ip", "N",
     "new connections per second from one address range (IPv4 /24, IPv6 /64; a burst of twice that), in 0..100000 "
     "(default 50; 0 = no limit); beyond it a connection is closed at accept, before it costs a session",
     ValueKind::number, false, [](ServerConfig& c, std::string_view v) { return parse_number(v, c.connect_rate_per_ip); },
     [](const ServerConfig& c) { return show_number(c.connect_rate_per_ip); }},
    {"handshake-timeout", "SECONDS", "close a connection that sends no Hello for this long, in (0, 60]", ValueKind::number,
     false, [](ServerConfig& c, std::string_view v) { return parse_number(v, c.handshake_timeout_s); },
     [](const ServerConfig& c) { return show_number(c.handshake_timeout_s); }},
    {"udp-redundancy", "N",
     "copies of up to N earlier unacknowledged frames in each UDP datagram (FrameBundle), so a lost datagram "
     "costs no frame; in 0..7",
     ValueKind::integer, false, [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.udp_redundancy); },
     [](const ServerConfig& c) { return std::to_string(c.udp_redundancy); }},
    {"admin-token-file", "PATH", "file holding the admin token (readable, non-empty); unset = no admin interface",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) -> std::string {
       c.admin_token_file = std::string(v);
       std::string contents;
       if (!read_file(c.admin_token_file, contents)) return "file '" + c.admin_token_file + "' cannot be read";
       c.admin_token = trim(contents);
       if (c.admin_token.empty()) return "file '" + c.admin_token_file + "' is empty";
       return {};
     },
     [](const ServerConfig& c) { return c.admin_token_file.empty() ? std::string("unset") : c.admin_token_file; }},
    {"cookie-key-file", "PATH", "file holding the 32-byte UDP cookie key as 64 hex digits, shared by replicas; unset = random per start",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) -> std::string {
       std::string contents;
       if (!read_file(std::string(v), contents)) return "file '" + std::string(v) + "' cannot be read";
       contents = trim(contents);
       if (contents.size() != 64) return hex_digit_error(v);
       c.cookie_key.clear();
       for (std::size_t i = 0; i < 64; i += 2) {
         unsigned value = 0;
         const auto [end, ec] = std::from_chars(contents.data() + i, contents.data() + i + 2, value, 16);
         if (ec != std::errc() || end != contents.data() + i + 2) return hex_digit_error(v);
         c.cookie_key.push_back(static_cast<std::uint8_t>(value));
       }
       return {};
     },
     [](const ServerConfig& c) { return std::string(c.cookie_key.empty() ? "unset" : "set"); }},
    {"timeline", "URL",
     "the fleet's timeline, etcd://HOST:PORT/PREFIX: admin changes are appended to its log in etcd and every "
     "server following it applies them at the same tick; unset = this server's changes are its own",
     ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) -> std::string {
       std::string error;
       if (!parse_timeline_url(v, error)) return error;
       c.timeline = std::string(v);
       return {};
     },
     [](const ServerConfig& c) { return c.timeline.empty() ? std::string("unset") : c.timeline; }},
    {"timeline-lease", "SECONDS",
     "the lease this server holds on the timeline's store, an integer in 2..300: a change waits for every "
     "server holding one, and a server cut off from the store streams no frame once its lease may have lapsed",
     ValueKind::integer, false,
     [](ServerConfig& c, std::string_view v) { return parse_integer(v, c.timeline_lease_s); },
     [](const ServerConfig& c) { return std::to_string(c.timeline_lease_s); }},
    {"idle-timeout", "SECONDS", "drop a client silent for this long, in (0, 3600]", ValueKind::number, false,
     [](ServerConfig& c, std::string_view v) { return parse_number(v, c.idle_timeout_s); },
     [](const ServerConfig& c) { return show_number(c.idle_timeout_s); }},
    {"log-level", "LEVEL", "trace, debug, info, warn, error, critical or off", ValueKind::text, false,
     [](ServerConfig& c, std::string_view v) {
       c.log_level = std::string(v);
       return std::string();
     },
     [](const ServerConfig& c) { return c.log_level; }},
};

}  // namespace

std::span<const ConfigOption> config_options() {
  static const std::vector<ConfigOption> options = [] {
    const std::span<const ConfigOption> transports = stream_listen_options();
    std::vector<ConfigOption> all(std::begin(kNetworkOptions), std::end(kNetworkOptions));
    all.insert(all.end(), transports.begin(), transports.end());
    all.insert(all.end(), std::begin(kOptions), std::end(kOptions));
    return all;
  }();
  return options;
}

const ConfigOption* find_config_option(std::string_view name) {
  for (const ConfigOption& option : config_options())
    if (option.name == name) return &option;
  return nullptr;
}

std::string describe_config(const ServerConfig& config) {
  std::string out;
  for (const ConfigOption& option : config_options()) {
    if (!out.empty()) out += ' ';
    out.append(option.name);
    out += '=';
    out += option.show(config);
  }
  out += " schedule-entries=";
  out += std::to_string(config.schedule.size());
  return out;
}

}  // namespace ocean::server
