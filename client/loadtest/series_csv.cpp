#include "series_csv.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

namespace ocean::loadtest {

void write_series_csv(std::ostream& out, std::span<const SeriesRow> rows) {
  out << "t_s,clients,kbps_mean,ok_pct,latency_p50_ms,latency_p99_ms,bad\n";
  char line[256];
  for (const SeriesRow& r : rows) {
    std::snprintf(line, sizeof line, "%.3f,%d,%.3f,%.3f,%.3f,%.3f,%llu\n", r.t_s, r.clients, r.kbps_mean, r.ok_pct,
                  r.latency_p50_ms, r.latency_p99_ms, static_cast<unsigned long long>(r.bad));
    out << line;
  }
}

std::string write_series_csv(const std::string& path, std::span<const SeriesRow> rows) {
  std::ofstream out(path);
  if (!out) return "--csv: cannot open '" + path + "' for writing";
  write_series_csv(out, rows);
  out.close();
  return out ? "" : "--csv: writing '" + path + "' failed";
}

namespace {

// Single quotes for a gnuplot string literal.
std::string gnuplot_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string plot_series(const std::string& csv_path, const std::string& png_path, const std::string& title) {
  const std::string script_path = png_path + ".gp";
  {
    std::ofstream gp(script_path);
    if (!gp) return "--plot: cannot write '" + script_path + "'";
    gp << "set terminal pngcairo size 1000,900 noenhanced\n"
       << "set output " << gnuplot_quoted(png_path) << "\n"
       << "set datafile separator ','\n"
       << "set key autotitle columnhead\n"
       << "set multiplot layout 3,1 title " << gnuplot_quoted(title) << " noenhanced\n"
       << "set grid\nset xlabel 'seconds'\n"
       << "set ylabel 'kbit/s per client'\nplot " << gnuplot_quoted(csv_path) << " using 1:3 with lines lw 2\n"
       << "set ylabel 'on-time %'\nset yrange [0:105]\nplot " << gnuplot_quoted(csv_path) << " using 1:4 with lines lw 2\n"
       << "set autoscale y\nset ylabel 'latency ms'\nplot " << gnuplot_quoted(csv_path)
       << " using 1:5 with lines lw 2, '' using 1:6 with lines lw 2\n"
       << "unset multiplot\n";
  }
  std::string shell_quoted = "'";
  for (char c : script_path) shell_quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  const std::string command = "gnuplot " + shell_quoted + "' 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0) return "--plot: gnuplot failed (exit " + std::to_string(WEXITSTATUS(status)) + "); is gnuplot installed?";
  std::remove(script_path.c_str());
  return "";
}

}  // namespace ocean::loadtest
