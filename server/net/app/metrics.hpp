// MetricsRegistry: counters, gauges and summaries with labels, rendered in the Prometheus text
// exposition format (version 0.0.4). Updates are lock-free for counters and gauges, so the
// simulation and network threads can record without contending; rendering takes a snapshot.
#pragma once

#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ocean::server {

using MetricLabels = std::vector<std::pair<std::string, std::string>>;  // name, value

class Counter {
 public:
  void inc(double amount = 1.0) { value_.fetch_add(amount, std::memory_order_relaxed); }
  double value() const { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<double> value_{0.0};
};

class Gauge {
 public:
  void set(double value) { value_.store(value, std::memory_order_relaxed); }
  void add(double amount) { value_.fetch_add(amount, std::memory_order_relaxed); }
  double value() const { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<double> value_{0.0};
};

// Count, sum and quantiles (0.5, 0.9, 0.99, max) over the most recent `window` observations.
class Summary {
 public:
  explicit Summary(std::size_t window = 1024);
  void observe(double value);

  struct Snapshot {
    std::uint64_t count = 0;
    double sum = 0.0;
    std::vector<std::pair<double, double>> quantiles;  // (q, value); empty before any observation
  };
  Snapshot snapshot() const;

 private:
  mutable std::mutex mutex_;
  std::vector<double> recent_;  // ring buffer
  std::size_t next_ = 0;
  std::uint64_t count_ = 0;
  double sum_ = 0.0;
};

class MetricsRegistry {
 public:
  // Returns the metric for (name, labels), creating it on first use. The reference stays valid for
  // the registry's lifetime. Throws std::invalid_argument for a malformed name or label name, or a
  // name already registered as another type (programming errors, found by the first test run).
  Counter& counter(std::string_view name, std::string_view help, const MetricLabels& labels = {});
  Gauge& gauge(std::string_view name, std::string_view help, const MetricLabels& labels = {});
  Summary& summary(std::string_view name, std::string_view help, const MetricLabels& labels = {});

  std::string render() const;  // text/plain; version=0.0.4

 private:
  enum class Type { counter, gauge, summary };
  struct Series {
    MetricLabels labels;
    std::unique_ptr<Counter> counter;
    std::unique_ptr<Gauge> gauge;
    std::unique_ptr<Summary> summary;
  };
  struct Family {
    Type type;
    std::string help;
    std::vector<std::unique_ptr<Series>> series;
  };
  Series& find_or_add(std::string_view name, std::string_view help, Type type, const MetricLabels& labels);

  mutable std::mutex mutex_;
  std::map<std::string, Family, std::less<>> families_;  // sorted: stable output
};

// Escapes a label value for the exposition format: backslash, double quote and newline.
std::string escape_label_value(std::string_view value);

}  // namespace ocean::server
