// libFuzzer harness for the config file reader: apply_config_toml on arbitrary TOML text, then
// validate_server_config and make_schedule on whatever it accepted. The file is trusted (the
// operator writes it), but a typo must give an error message, never a crash, hang or exception.
// Invariants: a refusal names the source; a config that validates yields a schedule without error.
#include <cstdint>
#include <string_view>

#include "config_loader.hpp"
#include "fuzz_check.hpp"
#include "server_config.hpp"

using namespace ocean::server;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ServerConfig config;
  const std::string error = apply_config_toml(config, text, "fuzz.toml");
  if (!error.empty()) {
    FUZZ_REQUIRE(error.rfind("fuzz.toml", 0) == 0);
    return 0;
  }
  if (!validate_server_config(config).empty()) return 0;
  std::string schedule_error;
  (void)make_schedule(config, schedule_error);
  FUZZ_REQUIRE(schedule_error.empty());
  return 0;
}
