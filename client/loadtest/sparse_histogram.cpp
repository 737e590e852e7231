#include "sparse_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::loadtest {

void SparseHistogram::add(double value) {
  if (!std::isfinite(value)) return;
  const double v = std::max(0.0, value);
  add_bin(static_cast<std::uint64_t>(v / width_), 1);
  note_max(v);
}

void SparseHistogram::add_bin(std::uint64_t bin, std::uint64_t count) {
  if (count == 0) return;
  bins_[bin] += count;
  count_ += count;
}

void SparseHistogram::merge(const SparseHistogram& other) {
  for (const auto& [bin, n] : other.bins_) add_bin(bin, n);
  note_max(other.max_);
}

double SparseHistogram::percentile(double p) const {
  if (count_ == 0) return 0.0;
  const double clamped = std::clamp(p, 0.0, 100.0);
  const auto rank = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(clamped / 100.0 * static_cast<double>(count_))));
  std::uint64_t seen = 0;
  for (const auto& [bin, n] : bins_) {
    seen += n;
    if (seen >= rank) return std::min(max_, static_cast<double>(bin + 1) * width_);
  }
  return max_;
}

}  // namespace ocean::loadtest
