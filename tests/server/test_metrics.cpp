#include "metrics.hpp"
#include "server_metrics.hpp"

#include <catch2/catch.hpp>

#include <ctime>
#include <fstream>

#include <cstring>
#include <map>
#include <set>
#include <regex>
#include <sstream>

using namespace ocean::server;

namespace {

struct Sample {
  std::string name;
  std::map<std::string, std::string> labels;  // unescaped values
  double value = 0.0;
};

// A reader of the exposition format, written from the spec, independent of the renderer:
// name{label="value",...} value, with \\, \" and \n escapes in label values.
bool parse_sample(const std::string& line, Sample& out) {
  static const std::regex name_re("^[a-zA-Z_:][a-zA-Z0-9_:]*");
  std::smatch match;
  if (!std::regex_search(line, match, name_re)) return false;
  out = {match.str(), {}, 0.0};
  std::size_t pos = match.length();
  if (pos < line.size() && line[pos] == '{') {
    ++pos;
    while (pos < line.size() && line[pos] != '}') {
      const std::size_t eq = line.find("=\"", pos);
      if (eq == std::string::npos) return false;
      const std::string label = line.substr(pos, eq - pos);
      if (!std::regex_match(label, std::regex("[a-zA-Z_][a-zA-Z0-9_]*"))) return false;
      std::string value;
      for (pos = eq + 2; pos < line.size() && line[pos] != '"'; ++pos) {
        if (line[pos] == '\\') {
          const char next = line.at(++pos);
          if (next == 'n') value += '\n';
          else if (next == '\\' || next == '"') value += next;
          else return false;
        } else if (line[pos] == '\n') {
          return false;
        } else {
          value += line[pos];
        }
      }
      if (pos >= line.size()) return false;
      ++pos;  // closing quote
      if (line[pos] == ',') ++pos;
      out.labels[label] = value;
    }
    if (pos >= line.size()) return false;
    ++pos;  // closing brace
  }
  if (pos >= line.size() || line[pos] != ' ') return false;
  const std::string value = line.substr(pos + 1);
  if (value == "+Inf" || value == "-Inf" || value == "NaN") return true;
  std::size_t used = 0;
  out.value = std::stod(value, &used);
  return used == value.size();
}

std::vector<Sample> parse_all(const std::string& text, std::vector<std::string>& bad_lines) {
  std::vector<Sample> samples;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# HELP ", 0) == 0 || line.rfind("# TYPE ", 0) == 0) continue;
    Sample sample;
    if (parse_sample(line, sample)) samples.push_back(sample);
    else bad_lines.push_back(line);
  }
  return samples;
}

const Sample* find(const std::vector<Sample>& samples, const std::string& name,
                   const std::map<std::string, std::string>& labels = {}) {
  for (const Sample& s : samples)
    if (s.name == name && s.labels == labels) return &s;
  return nullptr;
}

}  // namespace

TEST_CASE("every rendered line parses and carries its value", "[metrics]") {
  MetricsRegistry registry;
  registry.counter("ocean_test_total", "A counter.").inc(3);
  registry.counter("ocean_test_total", "A counter.").inc(2);  // same series
  registry.gauge("ocean_level", "A gauge.", {{"transport", "udp"}}).set(-1.5);
  registry.counter("ocean_rejects_total", "Rejects.", {{"reason", "bad_mac"}}).inc();
  registry.counter("ocean_rejects_total", "Rejects.", {{"reason", "expired"}}).inc(4);

  const std::string text = registry.render();
  std::vector<std::string> bad;
  const auto samples = parse_all(text, bad);
  CHECK(bad.empty());
  REQUIRE(find(samples, "ocean_test_total"));
  CHECK(find(samples, "ocean_test_total")->value == 5.0);
  CHECK(find(samples, "ocean_level", {{"transport", "udp"}})->value == -1.5);
  CHECK(find(samples, "ocean_rejects_total", {{"reason", "bad_mac"}})->value == 1.0);
  CHECK(find(samples, "ocean_rejects_total", {{"reason", "expired"}})->value == 4.0);
  CHECK(text.find("# TYPE ocean_rejects_total counter\n") != std::string::npos);
  CHECK(text.find("# TYPE ocean_level gauge\n") != std::string::npos);
  // One HELP and TYPE per family, however many series.
  CHECK(text.find("# TYPE ocean_rejects_total") == text.rfind("# TYPE ocean_rejects_total"));
  CHECK(text.back() == '\n');
}

TEST_CASE("label values with quotes, backslashes and newlines are escaped", "[metrics]") {
  MetricsRegistry registry;
  const std::string nasty = "a\"b\\c\nd}e,f=\"g";
  registry.counter("ocean_odd_total", "Help with a \\ and a\nnewline.", {{"reason", nasty}, {"x", ""}}).inc();
  const std::string text = registry.render();
  CHECK(text.find("# HELP ocean_odd_total Help with a \\\\ and a\\nnewline.\n") != std::string::npos);
  std::vector<std::string> bad;
  const auto samples = parse_all(text, bad);
  CHECK(bad.empty());
  REQUIRE(samples.size() == 1);
  CHECK(samples[0].labels.at("reason") == nasty);
  CHECK(samples[0].labels.at("x") == "");
  CHECK(escape_label_value("\\\"\n") == "\\\\\\\"\\n");
}

TEST_CASE("summaries report quantiles, sum and count over a window", "[metrics]") {
  MetricsRegistry registry;
  Summary& all = registry.summary("ocean_all_seconds", "All.");
  Summary& recent = registry.summary("ocean_recent_seconds", "Recent.", {{"profile", "mobile"}});
  (void)recent;
  for (int i = 100; i >= 1; --i) all.observe(i);  // order must not matter
  const Summary::Snapshot s = all.snapshot();
  CHECK(s.count == 100);
  CHECK(s.sum == 5050.0);
  REQUIRE(s.quantiles.size() == 4);
  CHECK(s.quantiles[0] == std::pair(0.5, 50.0));
  CHECK(s.quantiles[1] == std::pair(0.9, 90.0));
  CHECK(s.quantiles[2] == std::pair(0.99, 99.0));
  CHECK(s.quantiles[3] == std::pair(1.0, 100.0));

  Summary windowed(10);
  for (int i = 1; i <= 100; ++i) windowed.observe(i);
  const Summary::Snapshot w = windowed.snapshot();
  CHECK(w.count == 100);
  CHECK(w.quantiles[0].second == 95.0);  // median of 91..100 (nearest rank)
  CHECK(w.quantiles[3].second == 100.0);

  std::vector<std::string> bad;
  const auto samples = parse_all(registry.render(), bad);
  CHECK(bad.empty());
  CHECK(find(samples, "ocean_all_seconds", {{"quantile", "0.99"}})->value == 99.0);
  CHECK(find(samples, "ocean_all_seconds_count")->value == 100.0);
  CHECK(find(samples, "ocean_all_seconds_sum")->value == 5050.0);
  // Before any observation: count and sum only, no quantile lines.
  CHECK(find(samples, "ocean_recent_seconds_count", {{"profile", "mobile"}})->value == 0.0);
  CHECK_FALSE(find(samples, "ocean_recent_seconds", {{"profile", "mobile"}, {"quantile", "0.5"}}));
}

TEST_CASE("registration errors are caught", "[metrics]") {
  MetricsRegistry registry;
  registry.counter("ocean_x_total", "X.");
  CHECK_THROWS_WITH(registry.gauge("ocean_x_total", "X."), Catch::Contains("already registered as a counter"));
  CHECK_THROWS_WITH(registry.counter("9lives", "bad"), Catch::Contains("malformed"));
  CHECK_THROWS_WITH(registry.counter("ocean-dash", "bad"), Catch::Contains("malformed"));
  CHECK_THROWS_WITH(registry.counter("ocean_y", "bad", {{"bad-label", "v"}}), Catch::Contains("bad-label"));
  CHECK_THROWS_WITH(registry.summary("ocean_z", "bad", {{"quantile", "v"}}), Catch::Contains("reserved"));
}

TEST_CASE("server metrics register the documented families", "[metrics]") {
  MetricsRegistry registry;
  ServerMetrics metrics(registry);
  metrics.ticks.inc();
  metrics.ticks_skipped.inc(3);
  metrics.clients("mobile", "udp").set(2);
  metrics.frames_sent("tcp").inc(10);
  metrics.bytes_sent("tcp").inc(12345);
  metrics.rejects("server_full").inc();
  metrics.tick_seconds.observe(0.002);
  std::vector<std::string> bad;
  const auto samples = parse_all(registry.render(), bad);
  CHECK(bad.empty());
  CHECK(find(samples, "ocean_ticks_total")->value == 1.0);
  CHECK(find(samples, "ocean_ticks_skipped_total")->value == 3.0);
  CHECK(find(samples, "ocean_ticks_late_total")->value == 0.0);
  CHECK(find(samples, "ocean_clients", {{"profile", "mobile"}, {"transport", "udp"}})->value == 2.0);
  CHECK(find(samples, "ocean_frames_sent_total", {{"transport", "tcp"}})->value == 10.0);
  CHECK(find(samples, "ocean_bytes_sent_total", {{"transport", "tcp"}})->value == 12345.0);
  CHECK(find(samples, "ocean_rejects_total", {{"reason", "server_full"}})->value == 1.0);
  CHECK(find(samples, "ocean_tick_seconds", {{"quantile", "0.5"}})->value == 0.002);
  CHECK(find(samples, "ocean_encode_seconds_count") == nullptr);  // per profile, made when one encodes
  metrics.encode_seconds("mobile").observe(0.001);
  volatile double spin = 0.0;  // CPU time enough for a clock tick to show in /proc
  for (const auto start = std::clock(); std::clock() - start < CLOCKS_PER_SEC / 20;) spin = spin + 1.0;
  metrics.update_process();
  const auto more = parse_all(registry.render(), bad);
  CHECK(bad.empty());
  CHECK(find(more, "ocean_encode_seconds_count", {{"profile", "mobile"}})->value == 1.0);
  CHECK(find(more, "process_resident_memory_bytes")->value > 1e6);
  CHECK(find(more, "process_open_fds")->value >= 3.0);
  CHECK(find(more, "process_cpu_seconds_total")->value > 0.0);
  CHECK(find(more, "process_start_time_seconds")->value > 1.7e9);
  const Sample* build = nullptr;
  for (const Sample& sample : more)
    if (sample.name == "ocean_build_info") build = &sample;
  REQUIRE(build);
  CHECK(build->value == 1.0);
  CHECK(build->labels.at("protocol") == "4");
  CHECK(build->labels.at("codec") == "7");
  CHECK(!build->labels.at("version").empty());
}

TEST_CASE("README-server's metrics table names every family the server registers", "[metrics]") {
  MetricsRegistry registry;
  ServerMetrics metrics(registry);
  metrics.encode_seconds("mobile").observe(0.001);
  metrics.update_process();
  std::vector<std::string> bad;
  std::ifstream in(OCEAN_README_SERVER);
  REQUIRE(in);
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> families;
  for (const Sample& sample : parse_all(registry.render(), bad)) {
    std::string name = sample.name;
    for (const char* suffix : {"_sum", "_count"})
      if (name.size() > std::strlen(suffix) && name.compare(name.size() - std::strlen(suffix), std::string::npos, suffix) == 0 &&
          readme.find("`" + name + "`") == std::string::npos)
        name.resize(name.size() - std::strlen(suffix));  // a summary's series
    families.insert(name);
  }
  CHECK(families.size() > 30);
  for (const std::string& family : families) {
    INFO(family);
    CHECK(readme.find("`" + family + "`") != std::string::npos);
  }
}
