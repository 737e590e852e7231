// SeriesBoard: the per-second series of a run whose clients live on several threads. Each thread
// reports its share of a second (SecondPart); once every thread has reported it, the second's row
// is complete and, with progress on, printed. Rows are merged like summaries: sums and a merged
// latency histogram, never averages.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <vector>

#include "series_csv.hpp"
#include "sparse_histogram.hpp"

namespace ocean::loadtest {

struct SecondPart {
  int second = 0;
  int connected = 0;            // this thread's clients connected at the end of the second
  std::uint64_t bytes = 0;      // received by them during the second
  std::uint64_t frames = 0, ok = 0, bad = 0;
  SparseHistogram latency_s{1e-4};
};

class SeriesBoard {
 public:
  // threads: how many report each second; clients: the run's total, for the progress line.
  SeriesBoard(int threads, int clients, bool progress) : threads_(threads), clients_(clients), progress_(progress) {}

  void add(const SecondPart& part);  // thread-safe
  // One row per second reported by any thread, in order (a second some thread never reached,
  // because the run ended first, holds what the others saw).
  std::vector<SeriesRow> rows() const;

 private:
  struct Pending {
    SecondPart sum;
    int reports = 0;
  };
  static SeriesRow row_of(const SecondPart& sum);

  int threads_, clients_;
  bool progress_;
  mutable std::mutex mutex_;
  std::map<int, Pending> seconds_;
};

}  // namespace ocean::loadtest
