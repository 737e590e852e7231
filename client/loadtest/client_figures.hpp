// ConnectionFigures: how soon the clients of a run had a picture, and how bursty their downlink
// was, from per-client facts. The facts go into ConnectionParts (histograms and extremes), which
// merge across threads and processes; the figures are read from the parts, so one run and a
// merge of several agree on the arithmetic. Pure.
#pragma once

#include <optional>
#include <span>

#include "sparse_histogram.hpp"

namespace ocean::loadtest {

struct ClientConnectionFacts {
  std::optional<double> ttff_s;     // connection attempt start to first complete in-bound frame
  std::optional<double> peak_kbps;  // busiest 1 s from the first frame on (none: no such window)
  double startup_peak_kbps = 0.0;   // busiest 1 s that starts before the first frame
  std::optional<double> calm_kbps;  // median 1 s window from the first frame on
};

struct ConnectionFigures {
  // Time to first frame: a client's first connection attempt to its first complete frame within
  // the error bound; over the clients that got one (none: no client did).
  std::optional<double> ttff_max_s, ttff_p50_s;
  int clients_without_frame = 0;
  // Busiest 1 s a client received (envelopes included): the largest and the median client's, from
  // each client's first frame on, and the largest of the windows before it (the connection's start).
  double kbps_peak_1s = 0.0, kbps_peak_1s_p50 = 0.0, kbps_peak_1s_startup = 0.0;
  // The median client's median 100 ms rate from its first frame on: the stream between bursts.
  double kbps_calm = 0.0;
};

// Medians over clients come from these histograms: 1 ms bins for the first frame, 0.01 kbit/s for
// rates, finer than any figure is read to.
struct ConnectionParts {
  static constexpr double kTtffBinS = 1e-3;
  static constexpr double kKbpsBin = 0.01;
  SparseHistogram ttff_s{kTtffBinS}, peak_kbps{kKbpsBin}, calm_kbps{kKbpsBin};
  double startup_peak_kbps = 0.0;
  int clients_without_frame = 0;

  void add(const ClientConnectionFacts& client);
  void merge(const ConnectionParts& other);
  ConnectionFigures figures() const;
  bool operator==(const ConnectionParts&) const = default;
};

ConnectionFigures connection_figures(std::span<const ClientConnectionFacts> clients);

}  // namespace ocean::loadtest
