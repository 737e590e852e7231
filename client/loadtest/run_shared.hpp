// RunShared: what the threads of one load run share. Each thread (LoadShard) owns its clients,
// io_context, decode memos and verdicts; the truth is evaluated once per (tick, grid) for all of
// them under a lock, the per-second series is assembled on one board, and the last thread to end
// its measurement stamps the CPU readings.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>

#include "ground_truth.hpp"
#include "loadtest_options.hpp"
#include "series_board.hpp"
#include "stream_facts.hpp"

namespace ocean::loadtest {

struct RunShared {
  RunShared(const LoadtestOptions& o, int threads) : options(o), board(threads, o.clients, o.progress), unfinished(threads) {}

  const LoadtestOptions& options;
  double start_steady = 0.0, start_unix = 0.0, end_steady = 0.0;

  // The first Welcome fixes the stream's facts and creates the truth; both then never move.
  std::mutex truth_mutex;
  std::optional<StreamFacts> facts;  // under truth_mutex until set
  std::optional<GroundTruth> truth;  // under truth_mutex, always

  SeriesBoard board;

  std::atomic<int> unfinished;  // threads still measuring
  std::mutex stamp_mutex;
  double end_steady_stamp = 0.0, cpu_end_s = 0.0;
  std::optional<double> server_cpu_end_s;
};

}  // namespace ocean::loadtest
