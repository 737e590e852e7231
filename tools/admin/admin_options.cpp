#include "admin_options.hpp"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "number_list.hpp"
#include "query_flags.hpp"
#include "scene_names.hpp"
#include "scene_wire.hpp"

namespace ocean::admin {
namespace {

constexpr std::string_view kDescription =
    "ocean-admin: change the scene an ocean-server runs (wind, amplitude, choppiness, spectrum) or steer its vessels "
    "(add, course, remove, drop an object), or print the scene in force with --show. A change takes effect one "
    "second (the server's lead) after the server accepts it, on every session of that server only";

constexpr const char* kExitCodes =
    "exit codes: 0 done (the change was announced, or --show printed the scene); 2 usage or config "
    "(bad flag or value, unreadable token file); 3 refused by the server (unauthorized, out_of_range: its "
    "reason on stderr); 4 server unreachable, connection lost, or no answer within --timeout";

// The file's first line, trailing whitespace trimmed: a token file written by `echo` ends in \n,
// and that newline is not part of the token the server holds.
bool read_token_file(const std::string& path, std::string& token, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = "--token-file '" + path + "': cannot open it for reading";
    return false;
  }
  std::getline(in, token);
  while (!token.empty() && (token.back() == '\r' || token.back() == ' ' || token.back() == '\t')) token.pop_back();
  if (token.empty()) {
    error = "--token-file '" + path + "': the first line is empty; it must hold the admin token";
    return false;
  }
  return true;
}

// The token from --token-file, else from the environment; false with the reason when neither
// gives one the protocol carries.
bool read_admin_token(const std::string& token_file, const char* env_token, std::string& token, std::string& error) {
  if (!token_file.empty()) {
    if (!read_token_file(token_file, token, error)) return false;
  } else if (env_token && *env_token) {
    token = env_token;
  } else {
    error = "no admin token: give --token-file FILE or set OCEAN_ADMIN_TOKEN";
    return false;
  }
  if (token.size() > 128) {
    error = "the admin token is " + std::to_string(token.size()) + " bytes; the protocol allows at most 128";
    return false;
  }
  return true;
}

// The vessel flags (the server's config must have a [[vessel]] or [[drop]]: its streams then
// carry a wake), and the VesselCommand they make.
struct VesselFlags {
  std::string action, at, hull;
  std::uint32_t id = 0;
  double heading = 0.0, speed = 0.0, size = 2.0;

  CLI::Option* add_to(CLI::App& app) {
    app.add_option("--id", id, "the vessel's or object's id, 0..4294967295");
    app.add_option("--at", at, "X,Z: where, world metres inside the server's wake square");
    app.add_option("--hull", hull, "LENGTH,BEAM,DRAFT in metres (default 24,6,1.5)");
    app.add_option("--heading", heading, "degrees from +x towards +z (default 0)")->check(CLI::Range(-1e6, 1e6));
    app.add_option("--speed", speed, "m/s, [0, 20] (default 0)")->check(CLI::Range(0.0, 20.0));
    app.add_option("--size", size, "a dropped object's size, metres, (0, 50] (default 2)")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
              char* end = nullptr;
              const double v = std::strtod(text.c_str(), &end);
              return *end == '\0' && v > 0.0 && v <= 50.0 ? "" : "must be a size in (0, 50] metres, got " + text;
            },
            "(0, 50]"));
    return app.add_option("--vessel", action, "a vessel command, one second ahead: add (--id, --at, --hull, --heading, "
                                              "--speed), course (--id, --heading, --speed), remove (--id), drop (an "
                                              "object: --id, --at, --size)")
        ->check(CLI::IsMember({"add", "course", "remove", "drop"}));
  }

  bool command(protocol::ParamChange& change, std::string& error) const {
    static const std::map<std::string, wire::VesselAction> actions{{"add", wire::VesselAction::add},
                                                                   {"course", wire::VesselAction::course},
                                                                   {"remove", wire::VesselAction::remove},
                                                                   {"drop", wire::VesselAction::drop}};
    protocol::VesselCommand v;
    v.action = actions.at(action);  // IsMember checked it
    v.id = id;
    v.hull = {24.0, 6.0, 1.5};
    v.heading_deg = heading;
    v.speed_mps = speed;
    v.size_m = size;
    std::vector<double> xs;
    if (!hull.empty()) {
      if (!parse_numbers(hull, 3, xs)) return fail(error, "--hull '" + hull + "': give LENGTH,BEAM,DRAFT in metres, e.g. 24,6,1.5");
      v.hull = {xs[0], xs[1], xs[2]};
    }
    const bool placed = v.action == wire::VesselAction::add || v.action == wire::VesselAction::drop;
    if (placed && at.empty()) return fail(error, "--vessel " + action + " needs --at X,Z (world metres)");
    if (!at.empty()) {
      if (!parse_numbers(at, 2, xs)) return fail(error, "--at '" + at + "': give X,Z in metres, e.g. 40,-60");
      v.x_m = xs[0];
      v.z_m = xs[1];
    }
    change.vessel = v;
    return true;
  }

 private:
  static bool fail(std::string& error, std::string text) {
    error = std::move(text);
    return false;
  }
};

// The scene change flags. Their ranges are the protocol's (PROTOCOL.md 8, ParamChange): refusing
// here names the flag, where the server could only name the wire field.
struct SceneFlags {
  std::string spectrum;
  double wind_speed = 0, wind_dir = 0, amplitude = 0, choppiness = 0;
  CLI::Option *ws = nullptr, *wd = nullptr, *am = nullptr, *ch = nullptr, *sp = nullptr;

  void add_to(CLI::App& app) {
    ws = app.add_option("--wind-speed", wind_speed, "wind speed, m/s, [0, 100]")->check(CLI::Range(0.0, 100.0));
    wd = app.add_option("--wind-dir", wind_dir, "direction the wind blows towards, degrees from +x towards +z, "
                                                "[-1e6, 1e6]")->check(CLI::Range(-1e6, 1e6));
    am = app.add_option("--amplitude", amplitude, "scale on the spectrum's energy, [0, 1e6]")->check(CLI::Range(0.0, 1e6));
    ch = app.add_option("--choppiness", choppiness, "horizontal displacement scale, [0, 100]")->check(CLI::Range(0.0, 100.0));
    sp = app.add_option("--spectrum", spectrum, model::join_names(model::spectrum_names(), ", ", " or "))
             ->check(CLI::IsMember(model::spectrum_names()));
  }
  bool any() const { return *ws || *wd || *am || *ch || *sp; }
  void apply(protocol::ParamChange& c) const {
    if (*ws) c.wind_speed_mps = wind_speed;
    if (*wd) c.wind_dir_deg = wind_dir;
    if (*am) c.amplitude = amplitude;
    if (*ch) c.choppiness = choppiness;
    if (*sp) c.spectrum = scene_wire::to_wire(*model::spectrum_from_name(spectrum));  // IsMember checked it
  }
};

}  // namespace

AdminOptionsResult parse_admin_options(const std::vector<std::string>& args, const char* env_token) {
  AdminOptionsResult result;
  AdminOptions& o = result.options;
  CLI::App app{std::string(kDescription)};
  app.footer(kExitCodes);
  std::string server, token_file;
  app.add_option("--server", server, "HOST:PORT of the server's TCP listener")->required();
  app.add_option("--token-file", token_file, "file whose first line is the admin token (default: $OCEAN_ADMIN_TOKEN)");
  app.add_flag("--show", o.show, "print the scene in force (and any announced for later ticks) as JSON; needs no token");
  SceneFlags scene;
  scene.add_to(app);
  VesselFlags vessel;
  const CLI::Option* va = vessel.add_to(app);
  QueryFlags query;
  CLI::App* query_command = query.add_to(app);
  app.add_option("--timeout", o.timeout_s, "seconds to wait for the server, [0.1, 600]")->check(CLI::Range(0.1, 600.0));

  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    result.help = true;
    result.error = app.help();
    return result;
  } catch (const CLI::ParseError& e) {
    result.error = e.what();
    return result;
  }
  std::vector<client::ServerEndpoint> servers;
  if (!client::parse_server_list({server}, servers, result.error)) return result;
  if (servers.size() != 1) {
    // A change reaches only the replica it is sent to (README): one server, on purpose.
    result.error = "--server: '" + server + "' names " + std::to_string(servers.size()) +
                   " servers; ocean-admin changes one server at a time";
    return result;
  }
  o.server = servers.front();
  protocol::ParamChange& c = o.change;
  scene.apply(c);
  if (*va && !vessel.command(o.change, result.error)) return result;
  const bool change = scene.any() || *va;
  if (query_command->parsed()) {
    if (change || o.show) {
      result.error = "query asks and changes nothing: leave out --show and the change flags";
      return result;
    }
    if (!query.read(o, result.error)) return result;
    read_admin_token(token_file, env_token, o.query->admin_token, result.error);
    return result;
  }
  if (o.show == change) {
    result.error = o.show ? "--show prints the scene and changes nothing: leave out the change flags"
                          : "nothing to do: give --show, or at least one of --wind-speed, --wind-dir, "
                            "--amplitude, --choppiness, --spectrum, --vessel, or the query command";
    return result;
  }
  if (!o.show) read_admin_token(token_file, env_token, c.admin_token, result.error);
  return result;
}

}  // namespace ocean::admin
