#include "loadtest_options.hpp"

#include <CLI/CLI.hpp>
#include <cmath>

#include "load_run.hpp"
#include "profile.hpp"
#include "scenario.hpp"

namespace ocean::loadtest {
namespace {

std::string scenario_names() {
  std::string names;
  for (const Scenario& s : all_scenarios()) names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names;
}

std::string profile_names() {
  std::string names;
  for (const Profile& p : all_profiles()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

// What the command line gives as text or flags before it becomes LoadtestOptions.
struct Flags {
  std::vector<std::string> server;
  std::string bandwidth;
  bool quiet = false, own_decode = false;
};

void add_flags(CLI::App& app, LoadtestOptions& o, Flags& f) {
  app.add_option("--server", f.server,
                 "HOST:PORT of the server's TCP listener; a comma list (or the flag repeated) names replicas "
                 "a client fails over to, round robin");
  app.add_option("--clients", o.clients, "number of simulated clients, 1..100000");
  app.add_option("--ramp", o.ramp_s, "seconds over which the clients start, >= 0");
  app.add_option("--duration", o.duration_s, "seconds measured after the ramp, > 0");
  app.add_option("--scenario", o.scenario, "a named set of --profile/--transport/--link/--bandwidth (see --list-scenarios; some need a server started for them)");
  app.add_option("--profile", o.profile, "stream profile to ask for: " + profile_names());
  app.add_option("--transport", o.transport,
                 "udp, tcp, or ws (a browser's WebSocket: --server names the server's --ws-listen port; no UDP)");
  app.add_option("--link", o.link_text, "link impairment, e.g. rate=256kbit,delay=80ms,jitter=20ms,loss=5%,reorder=1%,dup=0.5% (\"\" or none = none)");
  app.add_option("--bandwidth", f.bandwidth,
                 "bandwidth each client announces in its Hello: bits/s or a rate such as 32kbit (0 = unstated; "
                 "default: the scenario's, else the link's rate)");
  app.add_option("--seed", o.seed, "seed of the link randomness (client i uses seed + i; give each process of a multi-machine run its own)");
  app.add_option("--threads", o.threads, "threads the clients are spread over, 1..256 (each its own event loop; pin with taskset, see SCENARIOS.md)");
  app.add_option("--merge", o.merge_paths,
                 "combine the --json summaries in these files (one per load-test process) into one summary and exit; "
                 "percentiles come from the merged histograms");
  app.add_option("--server-pid", o.server_pid, "pid of a local server, for server_cpu_pct from /proc");
  app.add_option("--expect-ok-pct", o.expect_ok_pct,
                 "fail (exit 5) when fewer frames than this % are verified and on time, or any frame is wrong")
      ->check(CLI::Range(0.0, 100.0));
  app.add_flag("--json", o.json, "print one JSON summary object as the last stdout line");
  app.add_flag("--quiet", f.quiet, "no progress line on stderr");
  app.add_flag("--list-scenarios", o.list_scenarios,
               "print the scenarios (with --json: as one JSON array, server needs included) and exit");
  app.add_flag("--no-shared-decode", f.own_decode,
               "every client decodes every frame itself (default: clients that got identical bytes on an identical "
               "state share one decode, which gives bit-identical frames at a fraction of the CPU)");
  app.add_option("--csv", o.csv_path, "write a per-second series to this CSV file");
  app.add_option("--plot", o.plot_path, "render kbps, on-time % and latency over time to this PNG (gnuplot)");
  app.add_option("--record", o.record_path, "record client 0's decoded frames: heights to this .npy file, each frame's tick to FILE.ticks.npy, every channel of every lattice to FILE.<channel>.npy (CODEC.md 10)");
}

// After parsing: the server list, the ranges, and the scenario filling in what was not given.
// Empty when the options are usable, else the message naming the flag.
std::string check_run(const CLI::App& app, LoadtestOptions& o, Flags& f) {
  std::string error;
  if (!client::parse_server_list(f.server, o.servers, error)) return error;
  o.host = o.servers.front().host;
  o.port = o.servers.front().port;
  if (o.threads < 1 || o.threads > 256)
    return "--threads: " + std::to_string(o.threads) + " is out of range; allowed 1..256";
  if (o.clients < 1 || o.clients > 100000)
    return "--clients: " + std::to_string(o.clients) + " is out of range; allowed 1..100000";
  if (!(o.ramp_s >= 0.0 && o.ramp_s <= 3600.0))
    return "--ramp: must be in [0, 3600] seconds";
  if (!(o.duration_s > 0.0 && o.duration_s <= 86400.0))
    return "--duration: must be in (0, 86400] seconds";
  const Scenario* scenario = nullptr;
  if (!o.scenario.empty()) {
    const Scenario* s = scenario = find_scenario(o.scenario);
    if (!s)
      return "--scenario: unknown scenario '" + o.scenario + "'; known: " + scenario_names();
    // The scenario fills in what was not given explicitly.
    if (app.count("--profile") == 0) o.profile = s->profile;
    if (app.count("--transport") == 0) o.transport = s->transport;
    if (app.count("--link") == 0) o.link_text = s->link;
  }
  if (!find_profile(o.profile))
    return "--profile: unknown profile '" + o.profile + "'; known: " + profile_names();
  if (o.transport != "udp" && o.transport != "tcp" && o.transport != "ws")
    return "--transport: '" + o.transport + "' is not udp, tcp or ws";
  if (o.link_text == "none") o.link_text.clear();
  if (!o.link_text.empty()) {
    LinkSpecResult link = parse_link_spec(o.link_text);
    if (!link.error.empty())
      return "--link: " + link.error;
    o.link = link.spec;
  }
  if (app.count("--bandwidth") == 0 && scenario && !scenario->bandwidth.empty()) f.bandwidth = scenario->bandwidth;
  if (!f.bandwidth.empty()) {
    const auto bps = parse_rate_bps(f.bandwidth);
    if (!bps || *bps > 1e12)
      return "--bandwidth: '" + f.bandwidth + "' is not a rate: bits/s, or e.g. 32kbit, 2mbit, 4kbps (bytes)";
    o.bandwidth_bps = static_cast<std::uint64_t>(std::llround(*bps));
  } else {
    o.bandwidth_bps = static_cast<std::uint64_t>(std::llround(o.link.rate_bps));  // what a client on it would know
  }
  return {};
}

}  // namespace

OptionsResult parse_options(const std::vector<std::string>& args) {
  OptionsResult result;
  LoadtestOptions& o = result.options;
  CLI::App app{"ocean-loadtest: N simulated clients on one or more threads, each behind a simulated link, every frame checked against the sim"};
  Flags f;
  f.server = {o.host + ":" + o.port};
  add_flags(app, o, f);
  app.footer(kExitTable);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    result.help = true;
    result.error = app.help();
    return result;
  } catch (const CLI::ParseError& e) {
    result.error = e.what();
    return result;
  }
  o.shared_decode = !f.own_decode;
  o.progress = !f.quiet;
  if (o.list_scenarios || !o.merge_paths.empty()) return result;
  result.error = check_run(app, o, f);
  return result;
}

}  // namespace ocean::loadtest
