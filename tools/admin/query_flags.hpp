// QueryFlags: `ocean-admin query` - the points (--at X,Z, repeated, or a --grid of them), the
// profile whose stream is asked, and how often to ask (--repeat, --rate: a game server's load).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "admin_options.hpp"

namespace ocean::admin {

struct QueryFlags {
  std::vector<std::string> at;
  std::string grid, profile;
  int repeat = 1;
  double rate_hz = 30.0;

  // The `query` subcommand, its flags bound here.
  CLI::App* add_to(CLI::App& app);
  // The HeightQuery the flags make, into `options`; false with a reason naming the flag.
  bool read(AdminOptions& options, std::string& error) const;
};

}  // namespace ocean::admin
