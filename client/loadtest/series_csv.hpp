// SeriesRow: one second of a load test (for --csv and --plot), and the CSV writer for them.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <string>

namespace ocean::loadtest {

struct SeriesRow {
  double t_s = 0.0;            // seconds since the first client started
  int clients = 0;             // connected at the end of the second
  double kbps_mean = 0.0;      // received kbit/s per connected client
  double ok_pct = 0.0;         // frames verified and on time over frames that arrived this second
  double latency_p50_ms = 0.0;
  double latency_p99_ms = 0.0;
  std::uint64_t bad = 0;       // frames beyond the error bound this second
};

void write_series_csv(std::ostream& out, std::span<const SeriesRow> rows);
// Writes the CSV to path; "" on success, otherwise why not.
std::string write_series_csv(const std::string& path, std::span<const SeriesRow> rows);
// Renders kbps, on-time % and latency over time with gnuplot from a CSV written above.
std::string plot_series(const std::string& csv_path, const std::string& png_path, const std::string& title);

}  // namespace ocean::loadtest
