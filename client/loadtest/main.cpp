// ocean-loadtest: parses the flags, runs the load, prints the table / JSON and writes the series.
// Exit status: kExitTable in load_run.hpp (0 ran, 1 an output not written, 2 bad flags,
// 3 no client connected, 4 all refused, 5 --expect-ok-pct not met or a frame wrong).
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "load_run.hpp"
#include "loadtest_options.hpp"
#include "scenario_listing.hpp"
#include "summary_merge.hpp"

namespace {

// --csv and --plot: 0, or 1 with the reason on stderr.
int write_series(const ocean::loadtest::LoadtestOptions& options, const std::vector<ocean::loadtest::SeriesRow>& series) {
  if (options.csv_path.empty() && options.plot_path.empty()) return 0;
  const std::string csv = options.csv_path.empty() ? options.plot_path + ".csv" : options.csv_path;
  if (std::string e = ocean::loadtest::write_series_csv(csv, series); !e.empty()) {
    std::cerr << "ocean-loadtest: " << e << "\n";
    return 1;
  }
  int status = 0;
  if (!options.plot_path.empty()) {
    const std::string title = "ocean-loadtest " + (options.scenario.empty() ? options.profile : options.scenario) + ", " +
                              std::to_string(options.clients) + " clients";
    if (std::string p = ocean::loadtest::plot_series(csv, options.plot_path, title); !p.empty()) {
      std::cerr << "ocean-loadtest: " << p << "\n";
      status = 1;
    }
    if (options.csv_path.empty()) std::remove(csv.c_str());
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ocean::loadtest;
  const OptionsResult parsed = parse_options(std::vector<std::string>(argv + 1, argv + argc));
  if (parsed.help) {
    std::cout << parsed.error;
    return 0;
  }
  if (!parsed.error.empty()) {
    std::cerr << "ocean-loadtest: " << parsed.error << "\n";
    return 2;
  }
  const LoadtestOptions& options = parsed.options;
  if (!options.merge_paths.empty()) {
    std::string error;
    const std::optional<LoadSummary> merged = merge_summary_files(options.merge_paths, error);
    if (!merged) {
      std::cerr << "ocean-loadtest: --merge: " << error << "\n";
      return 2;
    }
    print_table(options.json ? std::cerr : std::cout, *merged);
    if (options.json) std::cout << to_json(*merged) << std::endl;
    return 0;
  }
  if (options.list_scenarios) {
    if (options.json) std::cout << scenarios_json() << std::endl;
    else print_scenarios(std::cout);
    return 0;
  }
  try {
    const LoadRunResult result = run_load(options);
    const int status = write_series(options, result.series);
    print_table(options.json ? std::cerr : std::cout, result.summary);
    if (options.json) std::cout << to_json(result.summary) << std::endl;
    // Last, so it is the line a reader of the output sees.
    if (!result.error.empty()) {
      std::cerr << "ocean-loadtest: " << result.error << "\n";
      return result.exit_code;
    }
    const LoadSummary& s = result.summary;
    if (options.expect_ok_pct >= 0.0 && (s.frames_ok_pct < options.expect_ok_pct || s.frames_bad > 0)) {
      std::cerr << "ocean-loadtest: checks failed: " << s.frames_ok_pct << " % of frames verified and on time (--expect-ok-pct "
                << options.expect_ok_pct << "), " << s.frames_bad << " wrong\n";
      return kExitChecksFailed;
    }
    return status;
  } catch (const std::exception& e) {
    std::cerr << "ocean-loadtest: " << e.what() << "\n";
    return 1;
  }
}
