// AdminOptions: what ocean-admin is told on its command line, and its exit codes. Parsing never
// exits; an error names the flag and what it accepts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "message_types.hpp"
#include "server_list.hpp"

namespace ocean::admin {

// The exit codes, one per kind of failure, so scripts can tell a typo from a refusal from an outage.
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 2,        // bad flag or value, unreadable/empty token file, no token
  kExitRefused = 3,      // the server answered Error (unauthorized, out_of_range, ...)
  kExitUnreachable = 4,  // no connection, the connection dropped, or no answer in --timeout
};

struct AdminOptions {
  client::ServerEndpoint server;
  bool show = false;
  double timeout_s = 5.0;  // for the whole exchange
  // What the flags ask for, as it is sent: a field is present only when its flag was given
  // (absent = unchanged); the token from --token-file, else $OCEAN_ADMIN_TOKEN. request_id is the
  // caller's.
  protocol::ParamChange change;
  // `ocean-admin query`: the sea at points (HeightQuery), asked `query_repeat` times at
  // `query_rate_hz` (the token as above).
  std::optional<protocol::HeightQuery> query;
  int query_repeat = 1;
  double query_rate_hz = 30.0;
};

struct AdminOptionsResult {
  AdminOptions options;
  std::string error;  // empty on success
  bool help = false;  // --help: `error` holds the help text
};

// args excludes the program name; env_token is $OCEAN_ADMIN_TOKEN (null when unset).
AdminOptionsResult parse_admin_options(const std::vector<std::string>& args, const char* env_token);

}  // namespace ocean::admin
