#include "latency_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::loadtest {

void LatencyHistogram::add(double latency_s) {
  const double s = std::isfinite(latency_s) ? std::max(0.0, latency_s) : 10.0;
  const auto bin = std::min<std::size_t>(kBins - 1, static_cast<std::size_t>(s / kBinS));
  ++bins_[bin];
  ++count_;
  max_s_ = std::max(max_s_, s);
}

void LatencyHistogram::merge(const LatencyHistogram& other) {
  for (std::size_t i = 0; i < kBins; ++i) bins_[i] += other.bins_[i];
  count_ += other.count_;
  max_s_ = std::max(max_s_, other.max_s_);
}

void LatencyHistogram::clear() {
  std::fill(bins_.begin(), bins_.end(), 0);
  count_ = 0;
  max_s_ = 0.0;
}

SparseHistogram LatencyHistogram::sparse() const {
  SparseHistogram out(kBinS);
  for (std::size_t i = 0; i < kBins; ++i) out.add_bin(i, bins_[i]);
  out.note_max(max_s_);
  return out;
}

double LatencyHistogram::percentile(double p) const {
  if (count_ == 0) return 0.0;
  const double clamped = std::clamp(p, 0.0, 100.0);
  // Nearest rank: the smallest sample with at least p% of samples at or below it.
  const auto rank = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(clamped / 100.0 * count_)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < kBins; ++i) {
    seen += bins_[i];
    if (seen >= rank) return std::min(max_s_, (i + 1) * kBinS);
  }
  return max_s_;
}

}  // namespace ocean::loadtest
