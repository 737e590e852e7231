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

namespace {

std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("frame recorder: the ticks file sits beside the heights, int64, one per frame") {
  CHECK(ticks_path_for("/tmp/run.npy") == "/tmp/run.ticks.npy");
  CHECK(ticks_path_for("/tmp/run") == "/tmp/run.ticks.npy");
  const std::string path = "/tmp/ocean-loadtest-test-" + std::to_string(::getpid()) + ".npy";
  const std::string base = path.substr(0, path.size() - 4);
  {
    FrameRecorder recorder(path);
    ocean::codec::ReconstructedFrame frame;
    frame.height.assign(4 * 4, 0.5f);
    const std::vector<int> lattices{4};
    CHECK(recorder.append(5000000000LL, lattices, frame));  // beyond 32 bits: the file keeps it whole
    CHECK(recorder.append(5000000008LL, lattices, frame));
    recorder.close();
  }
  const std::vector<char> bytes = file_bytes(ticks_path_for(path));
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
  for (const std::string& f : {path, ticks_path_for(path), base + ".lattices.npy", base + ".height.npy", base + ".baselines.npy"})
    std::remove(f.c_str());
}

TEST_CASE("frame recorder: every channel the stream carries, over all its lattices, and nothing of another stream") {
  const std::string path = "/tmp/ocean-loadtest-channels-" + std::to_string(::getpid()) + ".npy";
  const std::string base = path.substr(0, path.size() - 4);
  const std::vector<int> lattices{4, 2};  // a cascaded stream: 16 + 4 samples a channel
  ocean::codec::ReconstructedFrame frame;
  frame.baseline = 8;  // a delta from tick 8
  for (std::vector<float>* c : {&frame.height, &frame.slope_x, &frame.slope_z, &frame.disp_x, &frame.disp_z,
                                &frame.disp_xx, &frame.disp_zz, &frame.disp_xz, &frame.jacobian})
    c->assign(20, 0.0f);
  for (int i = 0; i < 20; ++i) frame.jacobian[i] = 0.5f + static_cast<float>(i);
  {
    FrameRecorder recorder(path);
    CHECK(recorder.append(10, lattices, frame));
    CHECK(recorder.append(12, lattices, frame));
    const std::vector<int> other{4};  // after a reconnection to another profile
    CHECK_FALSE(recorder.append(14, other, frame));
    recorder.close();
  }
  const char* names[] = {"height", "slope_x", "slope_z", "disp_x", "disp_z", "disp_xx", "disp_zz", "disp_xz", "jacobian"};
  for (const char* name : names) {
    const std::vector<char> bytes = file_bytes(base + "." + name + ".npy");
    INFO(name);
    REQUIRE(bytes.size() == 128 + 2 * 20 * 4);
    CHECK_THAT(std::string(bytes.begin(), bytes.begin() + 128), Catch::Contains("'shape': (2, 1, 20)"));
  }
  // The second lattice's samples follow the first's, in each frame.
  const std::vector<char> jacobian = file_bytes(base + ".jacobian.npy");
  float last = 0.0f;
  std::memcpy(&last, jacobian.data() + 128 + 19 * 4, 4);
  CHECK(last == 19.5f);
  const std::vector<char> sizes = file_bytes(base + ".lattices.npy");
  REQUIRE(sizes.size() == 128 + 16);
  std::int64_t n0 = 0, n1 = 0;
  std::memcpy(&n0, sizes.data() + 128, 8);
  std::memcpy(&n1, sizes.data() + 136, 8);
  CHECK((n0 == 4 && n1 == 2));
  const std::vector<char> baselines = file_bytes(base + ".baselines.npy");
  REQUIRE(baselines.size() == 128 + 16);
  std::int64_t b0 = 0;
  std::memcpy(&b0, baselines.data() + 128, 8);
  CHECK(b0 == 8);
  // The first lattice's heights keep the file they always had.
  CHECK(file_bytes(path).size() == 128 + 2 * 16 * 4);
  // A stream without choppy channels writes no files for them.
  const std::string plain = "/tmp/ocean-loadtest-plain-" + std::to_string(::getpid()) + ".npy";
  {
    FrameRecorder recorder(plain);
    ocean::codec::ReconstructedFrame heights_only;
    heights_only.height.assign(16, 1.0f);
    CHECK(recorder.append(1, std::vector<int>{4}, heights_only));
    recorder.close();
  }
  const std::string plain_base = plain.substr(0, plain.size() - 4);
  CHECK(file_bytes(plain_base + ".jacobian.npy").empty());
  CHECK(file_bytes(plain_base + ".height.npy").size() == 128 + 16 * 4);
  for (const std::string& b : {base, plain_base}) {
    for (const char* name : names) std::remove((b + "." + name + ".npy").c_str());
    for (const char* f : {".npy", ".ticks.npy", ".lattices.npy", ".baselines.npy"}) std::remove((b + f).c_str());
  }
}
