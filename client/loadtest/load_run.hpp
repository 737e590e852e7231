// LoadRun: drives N ClientConnections on one io_context in one thread, each behind its own link
// models, checks every reconstructed frame against the shared GroundTruth, and adds it all up.
#pragma once

#include <functional>
#include <vector>

#include "load_summary.hpp"
#include "loadtest_options.hpp"
#include "series_csv.hpp"

namespace ocean::loadtest {

// ocean-loadtest's exit status (--help footer, README).
inline constexpr int kExitRan = 0;
inline constexpr int kExitFailure = 1;       // an output could not be written, or the run threw
inline constexpr int kExitUsage = 2;         // bad flags, or --merge inputs of different streams
inline constexpr int kExitUnreachable = 3;   // no client ever connected
inline constexpr int kExitRefused = 4;       // every client that reached a server was refused
inline constexpr int kExitChecksFailed = 5;  // --expect-ok-pct not met, or a frame was wrong
inline constexpr const char* kExitTable =
    "Exit status: 0 ran (or merged), 1 an output not written, 2 bad flags, 3 no client ever connected,\n"
    "4 every client was refused (reasons on stderr), 5 --expect-ok-pct not met or a frame was wrong.";

struct LoadRunResult {
  LoadSummary summary;
  std::vector<SeriesRow> series;
  // A failure that made the run meaningless: no client ever got a Welcome, or --record failed.
  std::string error;
  int exit_code = kExitRan;  // with error: kExitUnreachable, kExitRefused or kExitFailure
};

// Runs to completion (ramp + duration); progress lines go to stderr when options.progress.
LoadRunResult run_load(const LoadtestOptions& options);

}  // namespace ocean::loadtest
