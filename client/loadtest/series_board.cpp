#include "series_board.hpp"

#include <cstdio>

namespace ocean::loadtest {

SeriesRow SeriesBoard::row_of(const SecondPart& sum) {
  SeriesRow row;
  row.t_s = sum.second;
  row.clients = sum.connected;
  row.kbps_mean = sum.connected ? static_cast<double>(sum.bytes) * 8.0 / 1000.0 / sum.connected : 0.0;
  row.ok_pct = sum.frames ? 100.0 * static_cast<double>(sum.ok) / static_cast<double>(sum.frames) : 0.0;
  row.latency_p50_ms = sum.latency_s.percentile(50) * 1e3;
  row.latency_p99_ms = sum.latency_s.percentile(99) * 1e3;
  row.bad = sum.bad;
  return row;
}

void SeriesBoard::add(const SecondPart& part) {
  std::lock_guard lock(mutex_);
  Pending& p = seconds_[part.second];
  p.sum.second = part.second;
  p.sum.connected += part.connected;
  p.sum.bytes += part.bytes;
  p.sum.frames += part.frames;
  p.sum.ok += part.ok;
  p.sum.bad += part.bad;
  p.sum.latency_s.merge(part.latency_s);
  if (++p.reports != threads_ || !progress_) return;
  const SeriesRow row = row_of(p.sum);
  std::fprintf(stderr, "[%4ds] clients %d/%d  frames ok %.2f%%  bad %llu  kbps %.1f  p99 %.1f ms\n", part.second, row.clients,
               clients_, row.ok_pct, static_cast<unsigned long long>(row.bad), row.kbps_mean, row.latency_p99_ms);
}

std::vector<SeriesRow> SeriesBoard::rows() const {
  std::lock_guard lock(mutex_);
  std::vector<SeriesRow> rows;
  for (const auto& [second, p] : seconds_) rows.push_back(row_of(p.sum));
  return rows;
}

}  // namespace ocean::loadtest
