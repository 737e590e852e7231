// ConnectionFigures: how soon the clients of a run had a picture, and how bursty their downlink
// was, from per-client facts. Pure, so the load test and its unit tests agree on the arithmetic.
#pragma once

#include <optional>
#include <span>

namespace ocean::loadtest {

struct ClientConnectionFacts {
  std::optional<double> ttff_s;     // connection attempt start to first complete in-bound frame
  std::optional<double> peak_kbps;  // busiest 1 s from the first frame on (none: no such window)
  double startup_peak_kbps = 0.0;   // busiest 1 s that starts before the first frame
  std::optional<double> calm_kbps;  // median 1 s window from the first frame on
};

struct ConnectionFigures {
  // Over the clients that got a frame; none when no client did.
  std::optional<double> ttff_max_s, ttff_p50_s;
  int clients_without_frame = 0;
  double kbps_peak_1s = 0.0;      // the largest steady peak of any client
  double kbps_peak_1s_p50 = 0.0;  // the median client's steady peak
  double kbps_peak_1s_startup = 0.0;
  double kbps_calm = 0.0;         // the median client's calm rate
};

ConnectionFigures connection_figures(std::span<const ClientConnectionFacts> clients);

}  // namespace ocean::loadtest
