// Runs the real ocean-server binary: exit statuses, messages, and SIGTERM handling end to end.
#include <catch2/catch.hpp>

#include <csignal>
#include <string>
#include <vector>

#include "server_process.hpp"
#include "temp_file.hpp"

namespace {

using ocean::test_support::ServerOptions;
using ocean::test_support::ServerProcess;
using ocean::test_support::TempFile;

// The constructor does not wait for "listening": these servers are expected to exit, and the
// SIGTERM test checks the line itself.
ServerOptions run(std::vector<std::string> args) {
  ServerOptions options;
  options.args = std::move(args);
  options.wait_listening = false;
  return options;
}

const std::vector<std::string> kSmallServer = {"--listen", "127.0.0.1:0", "--metrics-listen", "off", "--size", "64",
                                               "--profiles", "lite,mobile"};

}  // namespace

TEST_CASE("ocean-server --help exits 0 and lists the options", "[process]") {
  ServerProcess child(run({"--help"}));
  CHECK(child.wait_exit(10) == 0);
  CHECK(child.log().find("--wind-speed") != std::string::npos);
  CHECK(child.log().find("--config FILE") != std::string::npos);
}

TEST_CASE("ocean-server refuses a bad value with status 2 and a message naming it", "[process]") {
  ServerProcess child(run({"--wind-speed", "150"}));
  CHECK(child.wait_exit(10) == 2);
  CHECK(child.log().find("--wind-speed") != std::string::npos);
  CHECK(child.log().find("[0, 100]") != std::string::npos);
}

TEST_CASE("ocean-server exits 2 on stderr for every configuration error of issue 18's list", "[process]") {
  // The systemd unit does not restart on 2: these must not exit 1 and be restarted forever.
  const std::vector<std::string> local = {"--listen", "127.0.0.1:0", "--metrics-listen", "off"};
  const TempFile out_of_range("wind-speed = 150.0\n"), bad_rate("seed = 1\ntick-rate = 7\n"), empty(""),
      negative_tick("[[schedule]]\ntick = -5\nwind-speed = 3.0\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--size", "64", "--profiles", "lite", "--epoch", "0"}, "ocean-server: --epoch 0: the current time is"},
      {{"--size", "16"}, "ocean-server: --profiles: profile 'mobile' streams a 64x64 grid, larger than the simulation (--size 16)"},
      {{"--config", out_of_range.path()}, "ocean-server: " + out_of_range.path() + ":1: --wind-speed"},
      {{"--config", bad_rate.path()}, "ocean-server: " + bad_rate.path() + ":2: --tick-rate 7"},
      {{"--config", empty.path()}, "ocean-server: --config: file '" + empty.path() + "' is empty"},
      {{"--config", "/tmp"}, "ocean-server: --config: '/tmp' is not a regular file"},
      {{"--config", negative_tick.path()},
       "ocean-server: " + negative_tick.path() + ":1: schedule entry 1: tick = -5 is negative"},
  };
  for (const auto& [args, message] : cases) {
    std::vector<std::string> all = local;
    all.insert(all.end(), args.begin(), args.end());
    ServerProcess child(run(all));
    CHECK(child.wait_exit(10) == 2);
    const std::string log = child.log();
    INFO(log);
    CHECK((log.rfind(message, 0) == 0 || log.find("\n" + message) != std::string::npos));
  }
}

TEST_CASE("ocean-server exits 0 on SIGTERM and on SIGINT", "[process]") {
  for (const int number : {SIGTERM, SIGINT}) {
    ServerProcess child(run(kSmallServer));
    REQUIRE(child.wait_for_output("listening", 20));
    child.signal(number);
    CHECK(child.wait_exit(10) == 0);
    INFO(child.log());
    CHECK(child.log().find("shutting down") != std::string::npos);
    CHECK(child.log().find("stopped") != std::string::npos);
  }
}
