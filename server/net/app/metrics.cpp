#include "metrics.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace ocean::server {
namespace {

bool valid_name(std::string_view name, bool allow_colon) {
  if (name.empty()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (allow_colon && c == ':');
    if (!letter && !(i > 0 && c >= '0' && c <= '9')) return false;
  }
  return true;
}

std::string format_value(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest round-trip form
  return std::string(buffer, result.ptr);
}

std::string escape_help(std::string_view help) {
  std::string out;
  for (const char c : help) {
    if (c == '\\') out += "\\\\";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

std::string format_labels(const MetricLabels& labels, const char* extra_name = nullptr, const std::string& extra = {}) {
  if (labels.empty() && !extra_name) return {};
  std::string out = "{";
  for (const auto& [name, value] : labels) out += name + "=\"" + escape_label_value(value) + "\",";
  if (extra_name) out += std::string(extra_name) + "=\"" + extra + "\",";
  out.back() = '}';
  return out;
}

const char* type_name(int type) {
  static const char* const names[] = {"counter", "gauge", "summary"};
  return names[type];
}

}  // namespace

std::string escape_label_value(std::string_view value) {
  std::string out;
  for (const char c : value) {
    if (c == '\\') out += "\\\\";
    else if (c == '"') out += "\\\"";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

Summary::Summary(std::size_t window) { recent_.reserve(std::max<std::size_t>(window, 1)); }

void Summary::observe(double value) {
  std::lock_guard lock(mutex_);
  if (recent_.size() < recent_.capacity()) {
    recent_.push_back(value);
  } else {
    recent_[next_] = value;
    next_ = (next_ + 1) % recent_.size();
  }
  ++count_;
  sum_ += value;
}

Summary::Snapshot Summary::snapshot() const {
  std::vector<double> sorted;
  Snapshot snapshot;
  {
    std::lock_guard lock(mutex_);
    sorted = recent_;
    snapshot.count = count_;
    snapshot.sum = sum_;
  }
  if (sorted.empty()) return snapshot;
  std::sort(sorted.begin(), sorted.end());
  for (const double q : {0.5, 0.9, 0.99, 1.0}) {
    // Nearest rank: the smallest value with at least q of the window at or below it.
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    snapshot.quantiles.emplace_back(q, sorted[rank == 0 ? 0 : rank - 1]);
  }
  return snapshot;
}

MetricsRegistry::Series& MetricsRegistry::find_or_add(std::string_view name, std::string_view help, Type type,
                                                      const MetricLabels& labels) {
  if (!valid_name(name, true)) throw std::invalid_argument("metric name '" + std::string(name) + "' is malformed");
  for (const auto& [label, value] : labels)
    if (!valid_name(label, false) || label.starts_with("__") || label == "quantile")
      throw std::invalid_argument("metric '" + std::string(name) + "': label name '" + label + "' is malformed or reserved");
  std::lock_guard lock(mutex_);
  auto it = families_.find(name);
  if (it == families_.end()) it = families_.emplace(std::string(name), Family{type, std::string(help), {}}).first;
  Family& family = it->second;
  if (family.type != type)
    throw std::invalid_argument("metric '" + std::string(name) + "' is already registered as a " +
                                type_name(static_cast<int>(family.type)));
  for (const auto& series : family.series)
    if (series->labels == labels) return *series;
  auto series = std::make_unique<Series>();
  series->labels = labels;
  if (type == Type::counter) series->counter = std::make_unique<Counter>();
  if (type == Type::gauge) series->gauge = std::make_unique<Gauge>();
  if (type == Type::summary) series->summary = std::make_unique<Summary>();
  family.series.push_back(std::move(series));
  return *family.series.back();
}

Counter& MetricsRegistry::counter(std::string_view name, std::string_view help, const MetricLabels& labels) {
  return *find_or_add(name, help, Type::counter, labels).counter;
}

Gauge& MetricsRegistry::gauge(std::string_view name, std::string_view help, const MetricLabels& labels) {
  return *find_or_add(name, help, Type::gauge, labels).gauge;
}

Summary& MetricsRegistry::summary(std::string_view name, std::string_view help, const MetricLabels& labels) {
  return *find_or_add(name, help, Type::summary, labels).summary;
}

std::string MetricsRegistry::render() const {
  std::lock_guard lock(mutex_);
  std::string out;
  for (const auto& [name, family] : families_) {
    out += "# HELP " + name + " " + escape_help(family.help) + "\n";
    out += "# TYPE " + name + " " + type_name(static_cast<int>(family.type)) + "\n";
    for (const auto& series : family.series) {
      if (series->counter) out += name + format_labels(series->labels) + " " + format_value(series->counter->value()) + "\n";
      if (series->gauge) out += name + format_labels(series->labels) + " " + format_value(series->gauge->value()) + "\n";
      if (series->summary) {
        const Summary::Snapshot s = series->summary->snapshot();
        for (const auto& [q, value] : s.quantiles)
          out += name + format_labels(series->labels, "quantile", format_value(q)) + " " + format_value(value) + "\n";
        out += name + "_sum" + format_labels(series->labels) + " " + format_value(s.sum) + "\n";
        out += name + "_count" + format_labels(series->labels) + " " + std::to_string(s.count) + "\n";
      }
    }
  }
  return out;
}

}  // namespace ocean::server
