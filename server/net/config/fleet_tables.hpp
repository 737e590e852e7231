// The config file's fleet: [[vessel]] tables (a hull and a track of timed waypoints) and [[drop]]
// tables (an object's splash, once or again and again, as a round hull present for a moment).
// Values are checked here for their form; validate_server_config checks the tracks they make.
// Also the two TOML helpers the config loader shares with them.
#pragma once

#include "server_config.hpp"

// Errors as values (toml::parse_result), not exceptions: a bad file is a message, not a throw.
#define TOML_EXCEPTIONS 0
#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocean::server {

// "FILE:LINE" of a node, for errors.
std::string at_line(std::string_view source, const toml::node& node);
// A number of a table, integers too.
std::optional<double> toml_number(const toml::node* node);

// [[vessel]]: id, length, beam, draft, repeat, waypoints = [[t, x, z], ...]; they replace
// config.vessels. Returns "" or the error naming the table and key.
std::string apply_vessel_tables(ServerConfig& config, const toml::node& node, std::string_view source);
// [[drop]]: id, x, z, size, at, splash, every, into `drops` (appended to the vessels once the
// whole file is read).
std::string apply_drop_tables(const toml::node& node, std::string_view source, std::vector<model::VesselTrack>& drops);

}  // namespace ocean::server
