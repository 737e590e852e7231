// run_load: the clients spread over --threads LoadShards, one thread each, sharing the truth and
// the per-second board; their summaries merge as the summaries of several processes do.
#include "load_run.hpp"

#include <chrono>
#include <memory>
#include <thread>

#include "load_shard.hpp"
#include "process_cpu.hpp"
#include "summary_merge.hpp"

namespace ocean::loadtest {
namespace {

std::string server_names(const LoadtestOptions& o) {
  std::string names;
  for (const client::ServerEndpoint& s : o.servers) names += (names.empty() ? "" : ",") + s.host + ":" + s.port;
  return names;
}

// The run's own figures over the merged parts: CPU over the measured time, the truth's work.
void add_run_figures(LoadSummary& s, const RunShared& shared, double cpu_start_s, std::optional<double> server_cpu_start_s) {
  const double wall = shared.end_steady_stamp - shared.start_steady;
  s.loadtest_cpu_pct = wall > 0 ? 100.0 * (shared.cpu_end_s - cpu_start_s) / wall : 0.0;
  s.server_cpu_pct.reset();
  if (server_cpu_start_s && shared.server_cpu_end_s && wall > 0)
    s.server_cpu_pct = 100.0 * (*shared.server_cpu_end_s - *server_cpu_start_s) / wall;
  s.truth_evaluations = shared.truth ? shared.truth->evaluations() : 0;
  s.scenes = shared.truth ? static_cast<int>(shared.truth->scenes()) : 0;
  s.processes = 1;
}

}  // namespace

LoadRunResult run_load(const LoadtestOptions& options) {
  const int threads = std::max(1, std::min(options.threads, options.clients));
  RunShared shared(options, threads);
  std::vector<std::unique_ptr<LoadShard>> shards;
  for (int t = 0; t < threads; ++t) shards.push_back(std::make_unique<LoadShard>(shared, t, threads));
  shared.start_steady = client::ClientConnection::now_s();
  shared.start_unix = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  shared.end_steady = shared.start_steady + options.ramp_s + options.duration_s;
  const double cpu_start = own_cpu_s();
  const std::optional<double> server_cpu_start = process_cpu_s(options.server_pid);
  {
    std::vector<std::jthread> workers;
    for (int t = 1; t < threads; ++t) workers.emplace_back([&shards, t] { shards[static_cast<std::size_t>(t)]->run(); });
    shards[0]->run();
  }
  LoadRunResult result;
  LoadSummary& total = result.summary;
  total.processes = 0;
  for (const auto& shard : shards) merge_into(total, shard->summary());  // one run: the streams agree
  add_run_figures(total, shared, cpu_start, server_cpu_start);
  finalize(total);
  result.series = shared.board.rows();
  for (const auto& shard : shards)
    if (result.error.empty()) result.error = shard->record_error();
  if (!result.error.empty()) result.exit_code = kExitFailure;
  if (total.clients_welcomed == 0) {
    // The figures of a run no client took part in are zeros, not a measurement.
    const std::string why = shards[0]->first_close_reason();
    const bool refused = !total.refusals.empty();
    result.error = std::string(refused ? "every client was refused by " : "no client ever connected to ") +
                   server_names(options) + " (client 0: " + (why.empty() ? "no answer" : why) + ")" +
                   (result.error.empty() ? "" : "; " + result.error);
    result.exit_code = refused ? kExitRefused : kExitUnreachable;
  }
  return result;
}

}  // namespace ocean::loadtest
