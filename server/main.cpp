// ocean-server: loads the configuration, then runs the Server until SIGINT or SIGTERM.
// The one place exceptions are caught: a failure to start is reported and exits non-zero.
#include "config_loader.hpp"
#include "config_options.hpp"
#include "server.hpp"
#include "server_log.hpp"
#include "session_hub.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using ocean::server::ConfigLoadResult;
  const std::vector<std::string> args(argv, argv + argc);
  ConfigLoadResult loaded = ocean::server::load_config(args);
  if (loaded.outcome == ConfigLoadResult::Outcome::show_help) {
    std::fputs(loaded.message.c_str(), stdout);
    return 0;
  }
  if (loaded.outcome == ConfigLoadResult::Outcome::error) {
    std::fprintf(stderr, "ocean-server: %s\n", loaded.message.c_str());
    return 2;
  }
  try {
    ocean::server::set_log_level(loaded.config.log_level);
    spdlog::info("ocean-server starting: {}", ocean::server::describe_config(loaded.config));
    ocean::server::Server server(std::move(loaded.config));
    ocean::server::SessionHub sessions(server);
    server.run();
    return 0;
  } catch (const std::exception& e) {
    spdlog::critical("ocean-server: {}", e.what());
    return 1;
  }
}
