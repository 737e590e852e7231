// Loads ServerConfig from the command line and an optional TOML file (--config FILE): defaults,
// then the file, then flags (a flag overrides the file). Nothing here exits or prints.
#pragma once

#include "server_config.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ocean::server {

// A config file, and its schedule, larger than this is refused: a real one is a few KB, and
// toml++ and the checks take seconds per MB.
inline constexpr std::size_t kMaxConfigBytes = 1u << 20;
inline constexpr std::size_t kMaxScheduleEntries = 10000;

struct ConfigLoadResult {
  enum class Outcome { run, show_help, show_json, error };
  Outcome outcome = Outcome::error;
  ServerConfig config;  // valid when outcome == run
  std::string message;  // the help text (--help, or --help-json's JSON), or the error naming the option and what is allowed
};

// args[0] is the program name, as in argv.
ConfigLoadResult load_config(const std::vector<std::string>& args);

// Applies a TOML document on top of `config` (top-level keys named like the flags, plus
// [[schedule]] entries). `source` names the document in errors. Returns "" or the error.
// `origins`, when given, receives "source:line" for each top-level key the text set (by option
// name), so that an error found later, on the whole configuration, can point at the line.
std::string apply_config_toml(ServerConfig& config, std::string_view toml_text, std::string_view source,
                              std::map<std::string, std::string>* origins = nullptr);

// The --help text.
std::string config_help(std::string_view program);

}  // namespace ocean::server
