// LatencyHistogram: end-to-end latencies in fixed 0.1 ms bins up to 10 s (one overflow bin), so
// millions of samples cost O(1) each and percentiles of a whole run or of one second are cheap.
#pragma once

#include <cstdint>
#include <vector>

#include "sparse_histogram.hpp"

namespace ocean::loadtest {

class LatencyHistogram {
 public:
  static constexpr double kBinS = 1e-4;
  static constexpr std::size_t kBins = 100000;  // 0 .. 10 s; later samples land in the last bin

  LatencyHistogram() : bins_(kBins, 0) {}

  void add(double latency_s);  // negative latencies (clock noise) count as 0
  void merge(const LatencyHistogram& other);
  void clear();

  std::uint64_t count() const { return count_; }
  // Nearest-rank percentile (p in [0, 100]) in seconds, the upper edge of its bin; 0 when empty.
  double percentile(double p) const;
  double max_s() const { return max_s_; }
  // The same counts in a form that travels in a summary and merges (bins of kBinS seconds).
  SparseHistogram sparse() const;

 private:
  std::vector<std::uint64_t> bins_;
  std::uint64_t count_ = 0;
  double max_s_ = 0.0;
};

}  // namespace ocean::loadtest
