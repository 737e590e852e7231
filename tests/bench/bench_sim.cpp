// ocean-bench sim: the median full simulation tick (heights + slopes + choppy) against the median of
// the bare FFTW executions that tick needs, measured alternately in the same run on one thread.
#include "bench.hpp"

#include "ocean.hpp"

#include <CLI/CLI.hpp>

#include "common/json_writer.hpp"

#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace {

using ocean::sim::Frame;
using ocean::sim::FrameRequest;
using ocean::sim::Ocean;
using ocean::model::SceneParams;

// CPU time of this thread: on a shared machine it leaves out the time other processes held the core
// (cache pollution from them remains), so it is reported next to the wall-clock figures.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

// Wall and CPU milliseconds of one call.
struct Timing {
  double wall_ms;
  double cpu_ms;
};
template <class F>
Timing timed(F&& f) {
  const double wall = ocean::bench::now_ms(), cpu = thread_cpu_ms();
  f();
  return {ocean::bench::now_ms() - wall, thread_cpu_ms() - cpu};
}

int default_iterations(int size) { return size <= 128 ? 400 : size <= 256 ? 300 : size <= 512 ? 150 : size <= 1024 ? 30 : 8; }

int run_sim(int argc, char** argv) {
  std::vector<int> sizes;
  int iterations = 0;
  bool json = false;
  double choppiness = 1.0;
  CLI::App app{"ocean-bench sim: full tick vs bare FFTs, one thread"};
  app.add_option("--size", sizes, "grid size N (N x N), repeatable; default 256 and 512");
  app.add_option("--iterations", iterations, "ticks per size (default depends on size)");
  app.add_option("--lambda", choppiness, "choppiness of the scene")->capture_default_str();
  app.add_flag("--json", json, "one JSON object per size");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (sizes.empty()) sizes = {256, 512};

  for (int size : sizes) {
    SceneParams params;
    params.size_x = params.size_z = size;
    params.choppiness = choppiness;
    if (const std::string error = ocean::model::validate(params); !error.empty()) {
      std::fprintf(stderr, "ocean-bench sim: %s\n", error.c_str());
      return 2;
    }
    Ocean ocean(params);
    const FrameRequest request{true, true};
    Frame frame, band;
    const int n = iterations > 0 ? iterations : default_iterations(size);
    const int band_n = size >= 64 ? 64 : size;
    std::vector<double> tick_ms, fft_ms, band_ms, tick_cpu, fft_cpu;
    for (int i = -5; i < n; ++i) {  // 5 warm-up rounds
      const double t = 1000.0 + i / 60.0;
      const Timing tick = timed([&] { ocean.evaluate(t, frame, request); });
      const Timing fft = timed([&] { ocean.execute_transforms_only(frame, request); });
      const Timing band_tick = timed([&] { ocean.evaluate_band(t, band_n, band_n, band, FrameRequest{true, false}); });
      if (i < 0) continue;
      tick_ms.push_back(tick.wall_ms);
      fft_ms.push_back(fft.wall_ms);
      band_ms.push_back(band_tick.wall_ms);
      tick_cpu.push_back(tick.cpu_ms);
      fft_cpu.push_back(fft.cpu_ms);
    }
    const double tick = ocean::bench::median(tick_ms);
    const double fft = ocean::bench::median(fft_ms);
    const double band_tick = ocean::bench::median(band_ms);
    const double tick_c = ocean::bench::median(tick_cpu);
    const double fft_c = ocean::bench::median(fft_cpu);
    const int transforms = ocean.transform_count(request);
    if (json) {
      ocean::common::JsonWriter out(ocean::common::JsonWriter::Style::compact);
      out.text("bench", "sim").integer("size", size).integer("iterations", n).fixed("tick_ms", tick, 4);
      out.fixed("fft_ms", fft, 4).fixed("ratio", tick / fft, 4).integer("transforms", transforms);
      out.fixed("tick_cpu_ms", tick_c, 4).fixed("fft_cpu_ms", fft_c, 4).fixed("ratio_cpu", tick_c / fft_c, 4);
      out.integer("band", band_n).fixed("band_tick_ms", band_tick, 4).integer("threads", 1);
      std::printf("%s\n", out.str().c_str());
    } else {
      std::printf("sim %4dx%-4d tick %.3f ms  bare FFTs %.3f ms (%d c2r)  ratio %.3f  (CPU time: %.3f / %.3f = %.3f)"
                  "  | %dx%d band tick %.3f ms  [median of %d]\n",
                  size, size, tick, fft, transforms, tick / fft, tick_c, fft_c, tick_c / fft_c, band_n, band_n,
                  band_tick, n);
    }
    std::fflush(stdout);
  }
  return 0;
}

const ocean::bench::Registrar sim_bench("sim", "spectral ocean tick vs its bare FFTs (--size N --json)", run_sim);

}  // namespace
