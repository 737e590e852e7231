// LoadtestOptions: everything ocean-loadtest is told on its command line, after a --scenario's
// values are filled in under the explicit flags. Parsing never exits: errors name the flag.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "link_spec.hpp"
#include "server_list.hpp"

namespace ocean::loadtest {

struct LoadtestOptions {
  std::string host = "127.0.0.1";  // servers[0], for messages
  std::string port = "7700";
  // --server's list: every client fails over round robin through it (ClientConnectionConfig::servers).
  std::vector<client::ServerEndpoint> servers{{"127.0.0.1", "7700"}};
  int clients = 10;
  double ramp_s = 1.0;       // clients start evenly spread over this long
  double duration_s = 10.0;  // measured time after the ramp
  std::string scenario;      // "" = none
  std::string profile = "mobile";
  std::string transport = "udp";
  std::string link_text;     // as given (or from the scenario); "" = no impairment
  LinkSpec link;
  // Hello.bandwidth_bps: --bandwidth, else the scenario's, else the link's rate (0 = unstated).
  std::uint64_t bandwidth_bps = 0;
  std::uint64_t seed = 1;    // link randomness; client i uses seed + i
  int server_pid = 0;       // 0 = none
  double expect_ok_pct = -1.0;  // --expect-ok-pct: below it (or any bad frame) the run fails with kExitChecksFailed
  bool json = false;
  bool progress = true;
  bool list_scenarios = false;
  // Threads the clients are spread over (client i on thread i % threads), each with its own
  // io_context, so that the load generator is not the bottleneck; clamped to the client count.
  int threads = 1;
  // --merge: the JSON summaries to combine instead of running (ocean-loadtest --merge A.json B.json).
  std::vector<std::string> merge_paths;
  bool shared_decode = true;  // clients of one stream share a DecodeMemo (exact; off = each decodes alone)
  std::string csv_path, plot_path, record_path;
};

struct OptionsResult {
  LoadtestOptions options;
  std::string error;  // empty on success; names the flag and what it accepts
  bool help = false;  // --help was given: `error` holds the help text
};

// args excludes the program name.
OptionsResult parse_options(const std::vector<std::string>& args);

}  // namespace ocean::loadtest
