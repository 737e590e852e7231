// The option table: every setting ocean-server accepts, once, with its help text and the parser
// that applies it. Flags (--wind-speed) and config-file keys (wind-speed = ...) both go through it.
#pragma once

#include "server_config.hpp"

#include <span>
#include <string>
#include <string_view>

namespace ocean::server {

// What a config-file value may be written as (a flag is always text).
enum class ValueKind {
  integer,         // 30
  number,          // 12.5 or 12
  number_or_text,  // 12.5 or "deep"
  text,            // "jonswap"
  text_list,       // ["mobile", "desktop"] or "mobile,desktop"
  integer_or_text, // 1763744400000 or "2026-11-21T17:00:00Z"
};

struct ConfigOption {
  std::string_view name;        // the flag without "--"; also the config-file key
  std::string_view value_name;  // shown in --help, e.g. "HZ"
  std::string_view help;        // what it does and what is allowed
  ValueKind kind;
  bool schedulable;             // may appear in a [[schedule]] entry (changes the scene only)
  // Applies the value; returns "" or what is wrong with it (the caller prefixes the option).
  std::string (*apply)(ServerConfig& config, std::string_view value);
  // The default, as text, for --help.
  std::string (*show)(const ServerConfig& config);
  // The scene fields (model::SceneParams) it sets, space-separated: a scene error names the flag.
  std::string_view scene_fields = {};
};

std::span<const ConfigOption> config_options();
const ConfigOption* find_config_option(std::string_view name);

// Every option as name=value on one line, for the startup log (the admin token itself is never shown).
std::string describe_config(const ServerConfig& config);

}  // namespace ocean::server
