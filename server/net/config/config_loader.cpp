#include "config_loader.hpp"

#include "ascii_text.hpp"
#include "config_options.hpp"
#include "fleet_tables.hpp"
#include "options_json.hpp"

#include <algorithm>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <map>
#include <sstream>

namespace ocean::server {
namespace {

constexpr std::string_view kDescription =
    "ocean-server: simulates a spectral ocean and streams it to thin clients over TCP/UDP.";

constexpr std::string_view kFileHelp =
    "Config file (--config FILE, TOML): top-level keys are the option names without '--'\n"
    "(e.g. wind-speed = 12.0, profiles = [\"mobile\", \"desktop\"], depth = \"deep\"); flags override the file.\n"
    "Scheduled scene changes: [[schedule]] tables, each with tick = T (absolute tick index from --epoch)\n"
    "and any of spectrum, spreading, wind-speed, wind-dir, fetch, amplitude, depth, choppiness, small-wave;\n"
    "each entry changes those values from tick T on, on top of the previous entry.\n"
    "Vessels: [[vessel]] tables, each with id = N, length, beam, draft (metres), repeat = true|false and\n"
    "waypoints = [[t, x, z], ...] (seconds from tick 0, world metres inside the --wake-size square from\n"
    "--wake-origin-x/z; a repeating track ends where it starts); up to 32 vessels, 64 waypoints each.\n"
    "Dropped objects: [[drop]] tables, each with id = N (not a vessel's), x, z (world metres), size\n"
    "(metres across, default 2), at (seconds from tick 0, default 0), splash (seconds it presses the\n"
    "water, default 1) and every (seconds: drops again every this long; default 0, once); they count\n"
    "as vessels towards the 32.\n"
    "SIGINT or SIGTERM stops the server cleanly (exit status 0).";

std::string describe_toml_type(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

std::string format_double(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string format_date_time(const toml::date_time& dt) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%04d-%02d-%02dT%02d:%02d:%02d.%09u", dt.date.year, dt.date.month, dt.date.day,
                dt.time.hour, dt.time.minute, dt.time.second, dt.time.nanosecond);
  std::string text = buffer;
  if (!dt.offset) return text;  // no zone: parse_epoch_ms refuses it with a message
  const int minutes = dt.offset->minutes;
  std::snprintf(buffer, sizeof buffer, "%c%02d:%02d", minutes < 0 ? '-' : '+', std::abs(minutes) / 60,
                std::abs(minutes) % 60);
  return text + buffer;
}

// The value as the option's text form, or "" with `error` set when its TOML type does not fit.
std::string toml_value_text(const ConfigOption& option, const toml::node& node, std::string& error) {
  const auto kind = option.kind;
  if (auto v = node.as_integer();
      v && (kind == ValueKind::integer || kind == ValueKind::number || kind == ValueKind::number_or_text ||
            kind == ValueKind::integer_or_text))
    return std::to_string(v->get());
  if (auto v = node.as_floating_point(); v && (kind == ValueKind::number || kind == ValueKind::number_or_text))
    return format_double(v->get());
  if (auto v = node.as_string(); v && kind != ValueKind::integer && kind != ValueKind::number) return v->get();
  if (auto v = node.as_date_time(); v && kind == ValueKind::integer_or_text) return format_date_time(v->get());
  if (auto array = node.as_array(); array && kind == ValueKind::text_list) {
    std::string joined;
    for (const toml::node& item : *array) {
      if (!item.is_string()) {
        error = "must be an array of strings";
        return {};
      }
      joined += (joined.empty() ? "" : ",") + item.as_string()->get();
    }
    return joined;
  }
  static const std::map<ValueKind, const char*> expected = {
      {ValueKind::integer, "an integer"},
      {ValueKind::number, "a number"},
      {ValueKind::number_or_text, "a number or a string"},
      {ValueKind::text, "a string"},
      {ValueKind::text_list, "an array of strings or a comma-separated string"},
      {ValueKind::integer_or_text, "an integer or a string"}};
  error = std::string("must be ") + expected.at(kind) + ", not " + describe_toml_type(node);
  return {};
}

std::string schedulable_names() {
  std::string names;
  for (const ConfigOption& option : config_options())
    if (option.schedulable) names += (names.empty() ? "" : ", ") + std::string(option.name);
  return names;
}

std::string apply_schedule(ServerConfig& config, const toml::node& node, std::string_view source) {
  const toml::array* entries = node.as_array();
  if (!entries || !entries->is_array_of_tables())
    return at_line(source, node) + ": 'schedule' must be an array of tables ([[schedule]])";
  if (entries->size() > kMaxScheduleEntries)
    return at_line(source, node) + ": " + std::to_string(entries->size()) + " schedule entries; at most " +
           std::to_string(kMaxScheduleEntries) + " are allowed";
  // Each entry's values are checked on a copy of the config without its schedule: copying the
  // growing schedule for every entry made a long file quadratic (1.4 s for 8000 entries).
  ServerConfig base = config;
  base.schedule.clear();
  config.schedule.reserve(entries->size());
  std::size_t index = 0;
  for (const toml::node& entry_node : *entries) {
    const toml::table& table = *entry_node.as_table();
    const std::string where = at_line(source, entry_node) + ": schedule entry " + std::to_string(++index);
    const toml::node* tick_node = table.get("tick");
    if (!tick_node || !tick_node->is_integer()) return where + ": needs tick = T (an integer tick index)";
    if (tick_node->as_integer()->get() < 0) return where + ": tick = " + std::to_string(tick_node->as_integer()->get()) +
                                                   " is negative; ticks count from the epoch (0 or more)";
    ScheduleEntry entry{tick_node->as_integer()->get(), {}};
    ServerConfig scratch = base;  // catches bad values here, where the line number is known
    for (auto&& [key, value] : table) {
      if (key.str() == "tick") continue;
      const ConfigOption* option = find_config_option(key.str());
      if (!option || !option->schedulable)
        return where + ": '" + std::string(key.str()) + "' cannot be scheduled (allowed: " + schedulable_names() + ")";
      std::string error;
      const std::string text = toml_value_text(*option, value, error);
      if (error.empty()) error = option->apply(scratch, text);
      if (!error.empty()) return where + ": " + std::string(key.str()) + " " + error;
      entry.settings.emplace_back(std::string(key.str()), text);
    }
    config.schedule.push_back(std::move(entry));
  }
  return {};
}

// The whole file, or a message: a directory, an empty file or one over kMaxConfigBytes is an
// operator's mistake that would otherwise start a server on the defaults (or parse for minutes).
std::string read_config_file(const std::string& path, std::string& text) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return "--config: file '" + path + "' cannot be read (no such file)";
  if (!std::filesystem::is_regular_file(path, error))
    return "--config: '" + path + "' is not a regular file" + (error ? " (" + error.message() + ")" : std::string());
  const auto size = std::filesystem::file_size(path, error);
  if (error) return "--config: file '" + path + "' cannot be read (" + error.message() + ")";
  if (size == 0) return "--config: file '" + path + "' is empty";
  if (size > kMaxConfigBytes)
    return "--config: file '" + path + "' has " + std::to_string(size) + " bytes; at most " +
           std::to_string(kMaxConfigBytes) + " are allowed";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  if (!in || !(buffer << in.rdbuf())) return "--config: file '" + path + "' cannot be read";
  text = buffer.str();
  return {};
}

// A whole-configuration error names the option ("--wind-speed: ..."); when the file set it, the
// file and line go first, since that is where the operator has to look.
std::string with_file_origin(const std::string& error, const std::map<std::string, std::string>& origins) {
  if (error.rfind("--", 0) != 0) return error;
  const std::size_t end = error.find_first_of(": ", 2);
  const auto origin = origins.find(error.substr(2, end == std::string::npos ? std::string::npos : end - 2));
  return origin == origins.end() ? error : origin->second + ": " + error;
}

// The config file first, then the flags given over it, then the check of the whole; "" or the
// first error, naming the file line a value came from.
std::string assemble_config(ServerConfig& config, const std::string& config_file, std::span<const ConfigOption> options,
                            const std::vector<CLI::Option*>& flags, const std::vector<std::string>& flag_values) {
  std::map<std::string, std::string> file_origins;  // option name -> "file:line", until a flag overrides it
  if (!config_file.empty()) {
    std::string text;
    if (std::string error = read_config_file(config_file, text); !error.empty()) return error;
    if (std::string error = apply_config_toml(config, text, config_file, &file_origins); !error.empty()) return error;
  }
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (flags[i]->count() == 0) continue;
    file_origins.erase(std::string(options[i].name));
    if (std::string error = options[i].apply(config, flag_values[i]); !error.empty())
      return "--" + std::string(options[i].name) + ": " + error;
  }
  if (std::string error = validate_server_config(config); !error.empty()) return with_file_origin(error, file_origins);
  return {};
}

}  // namespace

std::string apply_config_toml(ServerConfig& config, std::string_view toml_text, std::string_view source,
                              std::map<std::string, std::string>* origins) {
  if (toml_text.size() > kMaxConfigBytes)
    return std::string(source) + ": " + std::to_string(toml_text.size()) + " bytes; at most " +
           std::to_string(kMaxConfigBytes) + " are allowed";
  if (const auto bad = first_non_ascii(toml_text)) {
    const std::string_view before = toml_text.substr(0, *bad);
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    return std::string(source) + ":" + std::to_string(line) + ": byte " + std::to_string(*bad) +
           " is not ASCII (config files must be ASCII; give non-ASCII paths as flags)";
  }
  toml::parse_result parsed = toml::parse(toml_text, source);
  if (!parsed) {
    const toml::parse_error& error = parsed.error();
    return std::string(source) + ":" + std::to_string(error.source().begin.line) + ":" +
           std::to_string(error.source().begin.column) + ": " + std::string(error.description());
  }
  const toml::table& table = parsed.table();
  config.schedule.clear();
  const toml::node* schedule = nullptr;
  std::vector<model::VesselTrack> drops;
  for (auto&& [key, node] : table) {
    if (key.str() == "schedule") {
      schedule = &node;  // checked last, against the scene the whole file sets
      continue;
    }
    if (key.str() == "vessel") {
      if (std::string error = apply_vessel_tables(config, node, source); !error.empty()) return error;
      continue;
    }
    if (key.str() == "drop") {
      if (std::string error = apply_drop_tables(node, source, drops); !error.empty()) return error;
      continue;
    }
    const ConfigOption* option = find_config_option(key.str());
    if (!option)
      return at_line(source, node) + ": unknown key '" + std::string(key.str()) +
             "' (keys are the option names without '--'; see --help)";
    std::string error;
    const std::string text = toml_value_text(*option, node, error);
    if (error.empty()) error = option->apply(config, text);
    if (!error.empty()) return at_line(source, node) + ": " + std::string(key.str()) + " " + error;
    if (origins) (*origins)[std::string(key.str())] = at_line(source, node);
  }
  // Objects press on the water as vessels do, after them (validate_server_config checks both).
  config.vessels.insert(config.vessels.end(), drops.begin(), drops.end());
  return schedule ? apply_schedule(config, *schedule, source) : std::string();
}

std::string config_help(std::string_view program) {
  CLI::App app{std::string(kDescription), std::string(program)};
  const ServerConfig defaults;
  std::string ignored;
  for (const ConfigOption& option : config_options())
    app.add_option("--" + std::string(option.name), ignored,
                   std::string(option.help) + " [default: " + option.show(defaults) + "]")
        ->type_name(std::string(option.value_name));
  app.add_option("--config", ignored, "TOML file with any of these options (see below)")->type_name("FILE");
  bool ignored_flag = false;
  app.add_flag("--help-json", ignored_flag, "print the options (with their defaults) and the stream profiles as JSON, for tools, and exit");
  app.footer(std::string(kFileHelp));
  return app.help();
}

ConfigLoadResult load_config(const std::vector<std::string>& args) {
  ConfigLoadResult result;
  const std::string program = args.empty() ? "ocean-server" : args.front();
  CLI::App app{std::string(kDescription), program};
  const auto options = config_options();
  std::vector<std::string> flag_values(options.size());
  std::vector<CLI::Option*> flags;
  for (std::size_t i = 0; i < options.size(); ++i)
    flags.push_back(app.add_option("--" + std::string(options[i].name), flag_values[i])
                        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast));  // the last one wins
  std::string config_file;
  app.add_option("--config", config_file);
  bool help_json = false;
  app.add_flag("--help-json", help_json);

  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 wants them last-first
  if (!reversed.empty()) reversed.pop_back();
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    result.outcome = ConfigLoadResult::Outcome::show_help;
    result.message = config_help(program);
    return result;
  } catch (const CLI::ParseError& e) {
    result.message = std::string(e.what()) + " (run with --help for the options)";
    return result;
  }
  if (help_json) {
    result.outcome = ConfigLoadResult::Outcome::show_json;
    result.message = options_json();
    return result;
  }

  result.message = assemble_config(result.config, config_file, options, flags, flag_values);
  if (result.message.empty()) result.outcome = ConfigLoadResult::Outcome::run;
  return result;
}

}  // namespace ocean::server
