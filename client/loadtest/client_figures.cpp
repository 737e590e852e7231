#include "client_figures.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ocean::loadtest {
namespace {

// Nearest rank, as LatencyHistogram: the value at or below which half of them lie.
double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.5 * static_cast<double>(values.size())));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

}  // namespace

ConnectionFigures connection_figures(std::span<const ClientConnectionFacts> clients) {
  ConnectionFigures f;
  std::vector<double> ttff, peaks, calm;
  for (const ClientConnectionFacts& c : clients) {
    if (c.ttff_s) ttff.push_back(*c.ttff_s);
    else ++f.clients_without_frame;
    if (c.peak_kbps) peaks.push_back(*c.peak_kbps);
    if (c.calm_kbps) calm.push_back(*c.calm_kbps);
    f.kbps_peak_1s_startup = std::max(f.kbps_peak_1s_startup, c.startup_peak_kbps);
  }
  if (!ttff.empty()) {
    f.ttff_max_s = *std::max_element(ttff.begin(), ttff.end());
    f.ttff_p50_s = median(ttff);
  }
  if (!peaks.empty()) {
    f.kbps_peak_1s = *std::max_element(peaks.begin(), peaks.end());
    f.kbps_peak_1s_p50 = median(peaks);
  }
  if (!calm.empty()) f.kbps_calm = median(calm);
  return f;
}

}  // namespace ocean::loadtest
