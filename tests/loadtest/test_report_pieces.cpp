// Percentiles, the per-second CSV, the JSON summary and the recording.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>

#include "frame_recorder.hpp"
#include "latency_histogram.hpp"
#include "load_summary.hpp"
#include "series_csv.hpp"

using namespace ocean::loadtest;
using ocean::client::FrameRecorder;
using ocean::client::ticks_path_for;

TEST_CASE("latency histogram: nearest-rank percentiles to the bin") {
  LatencyHistogram h;
  CHECK(h.percentile(50) == 0.0);
  for (int ms = 1; ms <= 100; ++ms) h.add(ms / 1000.0);
  CHECK(h.count() == 100);
  CHECK(h.percentile(50) == Approx(0.050).margin(1.5 * LatencyHistogram::kBinS));
  CHECK(h.percentile(99) == Approx(0.099).margin(1.5 * LatencyHistogram::kBinS));
  CHECK(h.percentile(100) == Approx(0.100).margin(1.5 * LatencyHistogram::kBinS));
  CHECK(h.percentile(0) == Approx(0.001).margin(1.5 * LatencyHistogram::kBinS));

  LatencyHistogram tail;
  for (int i = 0; i < 98; ++i) tail.add(0.010);
  tail.add(0.5);
  tail.add(30.0);  // beyond the last bin: still counted, max kept
  CHECK(tail.percentile(98) == Approx(0.010).margin(1.5 * LatencyHistogram::kBinS));
  CHECK(tail.percentile(99) == Approx(0.5).margin(1.5 * LatencyHistogram::kBinS));
  CHECK(tail.max_s() == 30.0);
  h.merge(tail);
  CHECK(h.count() == 200);
  h.clear();
  CHECK(h.count() == 0);
}

TEST_CASE("series csv: header and one line per second") {
  std::vector<SeriesRow> rows{{1.0, 4, 22.5, 100.0, 8.0, 40.0, 0}, {2.0, 3, 21.0, 97.5, 9.5, 120.25, 2}};
  std::ostringstream out;
  write_series_csv(out, rows);
  CHECK(out.str() ==
        "t_s,clients,kbps_mean,ok_pct,latency_p50_ms,latency_p99_ms,bad\n"
        "1.000,4,22.500,100.000,8.000,40.000,0\n"
        "2.000,3,21.000,97.500,9.500,120.250,2\n");
  CHECK_FALSE(write_series_csv("/nonexistent-dir/x.csv", rows).empty());
}

TEST_CASE("summary json: the fields the CTest wrapper reads, server cpu only when known") {
  LoadSummary s;
  s.clients = 4;
  s.frames_ok_pct = 99.5;
  s.frames_bad = 0;
  s.profile = "mobile";
  s.link = "loss=5%";
  std::string j = to_json(s);
  CHECK_THAT(j, Catch::Contains("\"clients\":4"));
  CHECK_THAT(j, Catch::Contains("\"frames_ok_pct\":99.5"));
  CHECK_THAT(j, Catch::Contains("\"frames_bad\":0"));
  CHECK_THAT(j, Catch::Contains("\"link\":\"loss=5%\""));
  CHECK_THAT(j, !Catch::Contains("server_cpu_pct"));
  CHECK_THAT(j, Catch::Contains("\"ttff_max_s\":null"));
  CHECK_THAT(j, Catch::Contains("\"clients_without_frame\":0"));
  s.ttff_max_s = 1.25;
  s.kbps_peak_1s = 48;
  CHECK_THAT(to_json(s), Catch::Contains("\"ttff_max_s\":1.25"));
  CHECK_THAT(to_json(s), Catch::Contains("\"kbps_peak_1s\":48"));
  s.server_cpu_pct = 12.5;
  CHECK_THAT(to_json(s), Catch::Contains("\"server_cpu_pct\":12.5"));
  CHECK(j.find('\n') == std::string::npos);
}

TEST_CASE("frame recorder: the ticks file sits beside the heights, int64, one per frame") {
  CHECK(ticks_path_for("/tmp/run.npy") == "/tmp/run.ticks.npy");
  CHECK(ticks_path_for("/tmp/run") == "/tmp/run.ticks.npy");
  const std::string path = "/tmp/ocean-loadtest-test-" + std::to_string(::getpid()) + ".npy";
  {
    FrameRecorder recorder(path);
    const std::vector<float> heights(4 * 4, 0.5f);
    recorder.append(5000000000LL, 4, heights);  // beyond 32 bits: the file keeps it whole
    recorder.append(5000000008LL, 4, heights);
    recorder.close();
  }
  std::ifstream in(ticks_path_for(path), std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() == 128 + 16);
  const std::string header(bytes.begin(), bytes.begin() + 128);
  CHECK_THAT(header, Catch::Contains("'descr': '<i8'"));
  CHECK_THAT(header, Catch::Contains("'shape': (2,)"));
  CHECK(header.back() == '\n');
  std::int64_t first = 0, second = 0;
  std::memcpy(&first, bytes.data() + 128, 8);
  std::memcpy(&second, bytes.data() + 136, 8);
  CHECK(first == 5000000000LL);
  CHECK(second == 5000000008LL);
  std::remove(path.c_str());
  std::remove(ticks_path_for(path).c_str());
}
