// SparseHistogram: counts of values in fixed-width bins, kept only for the bins that were hit, so
// it can travel in a JSON summary and be merged: the merge of two runs' histograms is exactly the
// histogram of both runs' values, and its percentiles are those of the union. Averaging two runs'
// percentiles would not be. Percentiles use LatencyHistogram's rule (nearest rank, the bin's upper
// edge, never above the largest value), so a figure reads the same from either.
#pragma once

#include <cstdint>
#include <map>

namespace ocean::loadtest {

class SparseHistogram {
 public:
  explicit SparseHistogram(double bin_width = 1.0) : width_(bin_width) {}

  void add(double value);  // negative values (clock noise) count as 0; non-finite ones are skipped
  // A bin's count as read back from a summary (count 0 adds nothing).
  void add_bin(std::uint64_t bin, std::uint64_t count);
  // Both must have the same bin width (the summary's format fixes it per figure).
  void merge(const SparseHistogram& other);
  // The largest value added; a merge keeps the larger.
  void note_max(double value) {
    if (value > max_) max_ = value;
  }

  double bin_width() const { return width_; }
  std::uint64_t count() const { return count_; }
  double max() const { return max_; }
  const std::map<std::uint64_t, std::uint64_t>& bins() const { return bins_; }
  // Nearest-rank percentile (p in [0, 100]): the upper edge of the bin holding that rank, at most
  // max(); 0 when empty.
  double percentile(double p) const;

  bool operator==(const SparseHistogram&) const = default;

 private:
  double width_;
  std::map<std::uint64_t, std::uint64_t> bins_;
  std::uint64_t count_ = 0;
  double max_ = 0.0;
};

}  // namespace ocean::loadtest
