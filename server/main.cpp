// ocean-server: loads the configuration, then runs the Server until SIGINT or SIGTERM (SIGHUP is
// logged and reads the TLS certificate again, SIGPIPE ignored).
// The one place exceptions are caught. Exit status (README-server.md): 0 stopped by a signal,
// 2 a bad option or configuration (also those found only when the server is built: an epoch too
// far from now, no streamable profile), 1 a failure at run time (an address in use...). Every
// error goes to stderr as "ocean-server: message".
#include "config_loader.hpp"
#include "config_options.hpp"
#include "log_sink.hpp"
#include "server.hpp"
#include "server_log.hpp"
#include "session_hub.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using ocean::server::ConfigLoadResult;
  const std::vector<std::string> args(argv, argv + argc);
  ConfigLoadResult loaded = ocean::server::load_config(args);
  if (loaded.outcome == ConfigLoadResult::Outcome::show_help) {
    std::fputs(loaded.message.c_str(), stdout);
    std::fputs("\nExit status: 0 stopped by SIGINT/SIGTERM, 1 a failure at run time (address in use...),\n"
               "2 a bad option or configuration. Errors go to stderr as \"ocean-server: message\".\n",
               stdout);
    return 0;
  }
  if (loaded.outcome == ConfigLoadResult::Outcome::show_json) {
    std::fputs(loaded.message.c_str(), stdout);
    return 0;
  }
  if (loaded.outcome == ConfigLoadResult::Outcome::error) {
    std::fprintf(stderr, "ocean-server: %s\n", loaded.message.c_str());
    return 2;
  }
  try {
    ocean::server::install_log_sink();  // a log pipe whose reader goes away is counted, never fatal
    ocean::server::set_log_level(loaded.config.log_level);
    spdlog::info("ocean-server starting: {}", ocean::server::describe_config(loaded.config));
    const ocean::model::SceneParams& scene = loaded.config.scene;
    if (scene.spectrum == ocean::model::SpectrumKind::phillips &&
        (scene.spreading != ocean::model::SceneParams{}.spreading || scene.fetch_m != ocean::model::SceneParams{}.fetch_m))
      spdlog::warn("--spreading and --fetch shape JONSWAP only; the Phillips spectrum ignores them "
                   "(its own |k.w|^2 factor spreads it): use --spectrum jonswap");
    ocean::server::Server server(std::move(loaded.config));
    ocean::server::SessionHub sessions(server);
    server.run();
    return 0;
  } catch (const std::invalid_argument& e) {  // model::ParamError too: the configuration's fault
    std::fprintf(stderr, "ocean-server: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::critical("ocean-server: {}", e.what());
    std::fprintf(stderr, "ocean-server: %s\n", e.what());
    return 1;
  }
}
