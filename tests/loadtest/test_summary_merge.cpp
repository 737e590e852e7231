// Merging load-test summaries (--threads, --merge): sums, extremes, and percentiles from merged
// histograms that equal the percentiles of the union of the parts' samples; the JSON round trip.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <random>
#include <unistd.h>

#include "json_value.hpp"
#include "latency_histogram.hpp"
#include "load_summary.hpp"
#include "series_board.hpp"
#include "summary_merge.hpp"

using namespace ocean::loadtest;

namespace {

// A part as one process would report it: latencies drawn from its own distribution.
LoadSummary part(int clients, double latency_scale_s, std::uint64_t seed) {
  LoadSummary s;
  s.clients = s.clients_connected = s.clients_welcomed = clients;
  s.profile = "mobile";
  s.transport = "udp";
  s.frames_expected = 1000u * static_cast<unsigned>(clients);
  s.frames_received = s.frames_expected - 7;
  s.frames_ok = s.frames_received - 3;
  s.frames_bad = seed;  // distinct per part, so a sum is visible
  s.codec_rejections["unknown_baseline"] = seed;
  s.refusals["over_capacity"] = seed;
  s.not_welcomed["refused: over_capacity"] = seed;
  s.not_welcomed["connecting"] = 2 * seed;
  s.error_bound_m = 0.005;
  s.interpolation_delay_ms = 100;
  s.max_err_m = 0.001 * static_cast<double>(seed);
  s.bytes_received = 5000u * static_cast<unsigned>(clients);
  s.udp_datagrams = 300u * static_cast<unsigned>(clients);
  s.client_seconds = 10.0 * clients;
  s.loadtest_cpu_pct = 20;
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> latency(1.0 / latency_scale_s);
  LatencyHistogram h;
  for (int i = 0; i < 5000; ++i) h.add(latency(rng));
  s.latency_s = h.sparse();
  for (int c = 0; c < clients; ++c) {
    ClientConnectionFacts f;
    if (c % 5 != 0) f.ttff_s = 0.2 + 0.01 * c * static_cast<double>(seed);
    f.peak_kbps = 10.0 + c;
    f.calm_kbps = 5.0 + 0.1 * c;
    f.startup_peak_kbps = 40.0 + static_cast<double>(seed);
    s.connection.add(f);
  }
  finalize(s);
  return s;
}

}  // namespace

TEST_CASE("sparse histogram: the merge of two is the histogram of the union, percentiles included") {
  std::mt19937_64 rng(42);
  std::lognormal_distribution<double> value(-4.0, 1.0);
  LatencyHistogram a, b, all;
  for (int i = 0; i < 20000; ++i) {
    const double v = value(rng);
    (i % 3 == 0 ? a : b).add(v);
    all.add(v);
  }
  SparseHistogram merged = a.sparse();
  merged.merge(b.sparse());
  CHECK(merged == all.sparse());
  for (double p : {0.0, 1.0, 50.0, 90.0, 99.0, 99.9, 100.0}) {
    CHECK(merged.percentile(p) == all.percentile(p));  // exactly, not approximately
  }
  CHECK(merged.max() == all.max_s());
  SparseHistogram empty(0.5);
  CHECK(empty.percentile(50) == 0.0);
}

TEST_CASE("merge: counts summed, extremes kept, percentiles from the merged histograms") {
  const LoadSummary a = part(10, 0.004, 1), b = part(30, 0.020, 2);
  LoadSummary total;
  total.processes = 0;
  REQUIRE(merge_into(total, a).empty());
  REQUIRE(merge_into(total, b).empty());
  CHECK(total.clients == 40);
  CHECK(total.processes == 2);
  CHECK(total.frames_expected == a.frames_expected + b.frames_expected);
  CHECK(total.frames_ok == a.frames_ok + b.frames_ok);
  CHECK(total.frames_bad == 3);
  CHECK(total.codec_rejections.at("unknown_baseline") == 3);
  CHECK(total.refusals.at("over_capacity") == 3);
  CHECK(total.not_welcomed.at("refused: over_capacity") == 3);
  CHECK(total.not_welcomed.at("connecting") == 6);
  CHECK(total.max_err_m == b.max_err_m);
  CHECK(total.loadtest_cpu_pct == 40);  // two processes' CPU together
  CHECK(total.frames_ok_pct == Approx(100.0 * (a.frames_ok + b.frames_ok) / (a.frames_expected + b.frames_expected)));
  CHECK(total.kbps_mean == Approx(5000.0 * 40 * 8 / 1000 / 400));
  SparseHistogram latency = a.latency_s;
  latency.merge(b.latency_s);
  CHECK(total.latency_p99_ms == latency.percentile(99) * 1e3);
  CHECK(total.latency_p50_ms == latency.percentile(50) * 1e3);
  // Not the mean of the parts' percentiles: the 30-client part dominates the union.
  CHECK(total.latency_p99_ms != Approx((a.latency_p99_ms + b.latency_p99_ms) / 2).epsilon(0.01));
  ConnectionParts clients = a.connection;
  clients.merge(b.connection);
  CHECK(*total.ttff_p50_s == *clients.figures().ttff_p50_s);
  CHECK(total.clients_without_frame == 2 + 6);
  CHECK(total.kbps_peak_1s == 39.0);
  CHECK(total.kbps_peak_1s_startup == 42.0);

  LoadSummary other = part(5, 0.004, 3);
  other.profile = "lite";
  const LoadSummary before = total;
  CHECK_THAT(merge_into(total, other), Catch::Contains("profile"));
  CHECK(total.clients == before.clients);
}

TEST_CASE("summary json: read back as written, and merging files equals merging in memory") {
  const LoadSummary a = part(10, 0.004, 1), b = part(30, 0.020, 2);
  std::string error;
  const auto read = summary_from_json(to_json(a), error);
  REQUIRE(read);
  CHECK(error.empty());
  CHECK(to_json(*read) == to_json(a));

  const std::string dir = "/tmp/ocean-merge-test-" + std::to_string(::getpid());
  const std::vector<std::string> paths{dir + "-a.json", dir + "-b.json"};
  std::ofstream(paths[0]) << "progress line\n" << to_json(a) << "\n";
  std::ofstream(paths[1]) << to_json(b) << "\n\n";
  const auto merged = merge_summary_files(paths, error);
  REQUIRE(merged);
  LoadSummary total;
  total.processes = 0;
  merge_into(total, a);
  merge_into(total, b);
  CHECK(to_json(*merged) == to_json(total));
  // A merged summary merges again (a tree of merges gives the same as one).
  std::ofstream(paths[0]) << to_json(*merged) << "\n";
  CHECK(merge_summary_files(std::vector<std::string>{paths[0]}, error)->frames_expected == total.frames_expected);

  std::ofstream(paths[1]) << "{\"clients\": 3}\n";
  CHECK_FALSE(merge_summary_files(paths, error));
  CHECK_THAT(error, Catch::Contains(paths[1]));
  for (const std::string& p : paths) std::remove(p.c_str());
  CHECK_FALSE(merge_summary_files(paths, error));
}

TEST_CASE("json reader: values, big integers exact, errors say where") {
  std::string error;
  const auto v = parse_json(R"( {"a": [1, 2.5, -3e2], "b": {"c": "x\"y\n"}, "n": null, "t": true, "big": 18446744073709551615} )", error);
  REQUIRE(v);
  CHECK(v->find("a")->items.at(2).number == -300.0);
  CHECK(v->find("b")->find("c")->text == "x\"y\n");
  CHECK(v->find("n")->kind == JsonValue::Kind::null);
  CHECK(v->find("t")->flag);
  CHECK(*v->find("big")->as_uint() == 18446744073709551615ull);
  CHECK_FALSE(v->find("a")->items.at(1).as_uint());
  CHECK_FALSE(parse_json("{\"a\": }", error));
  CHECK_THAT(error, Catch::Contains("at byte"));
  CHECK_FALSE(parse_json("[1] 2", error));
  CHECK_FALSE(parse_json(std::string(100, '['), error));
}

TEST_CASE("series board: a second's row adds up every thread's share, latency from the merged bins") {
  SeriesBoard board(2, 30, false);
  SecondPart a, b;
  a.second = b.second = 1;
  a.connected = 10;
  b.connected = 20;
  a.bytes = 10000;
  b.bytes = 20000;
  a.frames = 100;
  a.ok = 90;
  b.frames = 300;
  b.ok = 300;
  b.bad = 2;
  for (int i = 1; i <= 100; ++i) a.latency_s.add(0.001 * i);
  for (int i = 0; i < 300; ++i) b.latency_s.add(0.2);
  board.add(a);
  board.add(b);
  SecondPart late;  // the run ended before the other thread reached second 2
  late.second = 2;
  late.connected = 5;
  late.frames = late.ok = 10;
  board.add(late);
  const std::vector<SeriesRow> rows = board.rows();
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].clients == 30);
  CHECK(rows[0].kbps_mean == Approx(30000 * 8.0 / 1000 / 30));
  CHECK(rows[0].ok_pct == Approx(100.0 * 390 / 400));
  CHECK(rows[0].bad == 2);
  CHECK(rows[0].latency_p50_ms == Approx(200.0));  // 300 of the 400 samples are 0.2 s
  CHECK(rows[1].clients == 5);
  CHECK(rows[1].ok_pct == 100.0);
}
