// LoadRun: drives N ClientConnections on one io_context in one thread, each behind its own link
// models, checks every reconstructed frame against the shared GroundTruth, and adds it all up.
#pragma once

#include <functional>
#include <vector>

#include "load_summary.hpp"
#include "loadtest_options.hpp"
#include "series_csv.hpp"

namespace ocean::loadtest {

struct LoadRunResult {
  LoadSummary summary;
  std::vector<SeriesRow> series;
  // A failure that made the run meaningless: no client ever got a Welcome, or --record failed.
  std::string error;
};

// Runs to completion (ramp + duration); progress lines go to stderr when options.progress.
LoadRunResult run_load(const LoadtestOptions& options);

}  // namespace ocean::loadtest
