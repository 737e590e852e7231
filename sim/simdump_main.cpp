// ocean-simdump: evaluates one tick of a scene and prints what it computed (--summary), a 64-bit
// hash of every field's bytes (--hash, for the cross-process determinism test) or both as JSON.
#include "frame_hash.hpp"
#include "ocean.hpp"
#include "scene_names.hpp"

#include <CLI/CLI.hpp>

#include "common/json_writer.hpp"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using ocean::sim::Frame;
using ocean::sim::FrameRequest;
using ocean::model::SceneParams;

struct Options {
  SceneParams scene;
  double time_s = 0.0;
  int size = 0;  // sets both axes when given
  double patch_m = 0.0;
  int band = 0;  // 0 = the full frame
  bool choppy = false;
  bool no_slopes = false;
  double lambda = 1.0;
  std::string spectrum = std::string(ocean::model::spectrum_name(SceneParams{}.spectrum));
  std::string spreading = std::string(ocean::model::spreading_name(SceneParams{}.spreading));
  bool summary = false;
  bool hash = false;
  bool json = false;
};

struct FieldStats {
  double min = 0.0, max = 0.0, mean = 0.0, std = 0.0;
};

FieldStats stats(const std::vector<float>& v) {
  FieldStats s;
  if (v.empty()) return s;
  double sum = 0.0, sum2 = 0.0;
  s.min = s.max = v[0];
  for (float x : v) {
    s.min = std::min<double>(s.min, x);
    s.max = std::max<double>(s.max, x);
    sum += x;
  }
  s.mean = sum / v.size();
  for (float x : v) sum2 += (x - s.mean) * (x - s.mean);
  s.std = std::sqrt(sum2 / v.size());
  return s;
}

double max_slope(const Frame& f) {
  double m = 0.0;
  for (std::size_t i = 0; i < f.slope_x.size(); ++i) m = std::max(m, std::hypot(double(f.slope_x[i]), f.slope_z[i]));
  return m;
}

double fraction_below(const std::vector<float>& v, float threshold) {
  if (v.empty()) return 0.0;
  return double(std::count_if(v.begin(), v.end(), [=](float x) { return x < threshold; })) / v.size();
}

struct Tick {
  Frame frame;
  double median_ms = 0.0;
};

Tick run_tick(ocean::sim::Ocean& ocean, const Options& o, FrameRequest request, int repeats) {
  Tick tick;
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    if (o.band)
      ocean.evaluate_band(o.time_s, o.band, o.band, tick.frame, request);
    else
      ocean.evaluate(o.time_s, tick.frame, request);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  tick.median_ms = ms[ms.size() / 2];
  return tick;
}

void print_summary(const ocean::sim::Ocean& ocean, const Options& o, const Tick& tick) {
  const SceneParams& p = ocean.params();
  const Frame& f = tick.frame;
  const FieldStats h = stats(f.height);
  std::printf("ocean-simdump: one tick of the scene\n");
  std::printf("  grid       %d x %d%s\n", f.n_x, f.n_z, o.band ? " (band of the full grid)" : " (full frame)");
  std::printf("  full grid  %d x %d over a %g x %g m patch (dx = %g m)\n", p.size_x, p.size_z, p.patch_x_m,
              p.patch_z_m, p.patch_x_m / f.n_x);
  std::string spectrum_name(ocean::model::spectrum_name(p.spectrum));
  if (p.spectrum == ocean::model::SpectrumKind::jonswap)
    spectrum_name += " (" + std::string(ocean::model::spreading_name(p.spreading)) + ")";
  std::printf("  spectrum   %s, wind %g m/s towards %g deg, fetch %g m, amplitude %g, depth %g m, seed %" PRIu64
              "\n",
              spectrum_name.c_str(), p.wind_speed_mps, p.wind_dir_deg, p.fetch_m, p.amplitude, p.depth_m, p.seed);
  std::printf("  time       %g s\n", f.time_s);
  std::printf("  height     min %.4g m, max %.4g m, mean %.3g m, std %.4g m\n", h.min, h.max, h.mean, h.std);
  std::printf("  Hs         %.4g m (4 std); %.4g m expected from the spectrum of the full grid\n", 4.0 * h.std,
              4.0 * std::sqrt(ocean.expected_variance()));
  if (!f.slope_x.empty()) std::printf("  slope      max |grad h| %.4g\n", max_slope(f));
  if (!f.disp_x.empty()) {
    const FieldStats jac = stats(f.jacobian);
    std::printf("  choppy     lambda %g, max |D| %.4g m, Jacobian min %.4g mean %.6g, %.2f%% of points below 0.3\n",
                p.choppiness, std::max(stats(f.disp_x).max, stats(f.disp_z).max), jac.min, jac.mean,
                100.0 * fraction_below(f.jacobian, 0.3f));
  }
  std::printf("  tick       %.3f ms (median of 10 evaluations, %d inverse FFTs, one thread)\n", tick.median_ms,
              ocean.transform_count({!o.no_slopes, o.choppy}));
  std::printf("  hash       %016" PRIx64 "\n", ocean::sim::frame_hash(f));
}

void print_json(const ocean::sim::Ocean& ocean, const Options& o, const Tick& tick) {
  const Frame& f = tick.frame;
  const FieldStats h = stats(f.height);
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016" PRIx64, ocean::sim::frame_hash(f));
  ocean::common::JsonWriter json(ocean::common::JsonWriter::Style::compact);
  json.integer("n_x", f.n_x).integer("n_z", f.n_z).number("time_s", f.time_s, 17);
  json.text("spectrum", ocean::model::spectrum_name(ocean.params().spectrum));
  json.number("height_min", h.min, 9).number("height_max", h.max, 9).number("height_std", h.std, 9);
  json.number("hs", 4.0 * h.std, 9).number("expected_hs", 4.0 * std::sqrt(ocean.expected_variance()), 9);
  json.number("max_slope", max_slope(f), 9).fixed("tick_ms", tick.median_ms, 4);
  json.integer("transforms", ocean.transform_count({!o.no_slopes, o.choppy})).text("hash", hash);
  std::printf("%s\n", json.str().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  SceneParams& s = o.scene;
  CLI::App app{"ocean-simdump: evaluate one tick of an ocean scene and print it (summary, hash or JSON)"};
  app.add_flag("--summary", o.summary, "human-readable summary of the tick (the default)");
  app.add_flag("--hash", o.hash, "print only the 64-bit FNV-1a hash of the frame's dimensions and fields");
  app.add_flag("--json", o.json, "print one JSON object with the summary figures and the hash");
  app.add_option("--time", o.time_s, "time t in seconds");
  app.add_option("--size", o.size, "grid size N for both axes (power of two, 16..2048)");
  app.add_option("--size-x", s.size_x, "grid size along x");
  app.add_option("--size-z", s.size_z, "grid size along z");
  app.add_option("--patch", o.patch_m, "patch size in metres for both axes");
  app.add_option("--band", o.band, "evaluate the central band x band modes instead of the full frame");
  app.add_flag("--choppy", o.choppy, "also compute choppy displacement and its Jacobian");
  app.add_option("--lambda", o.lambda, "choppiness used with --choppy")->capture_default_str();
  app.add_flag("--no-slopes", o.no_slopes, "skip the slope fields");
  app.add_option("--seed", s.seed, "random seed of h0");
  using ocean::model::join_names;
  app.add_option("--spectrum", o.spectrum, join_names(ocean::model::spectrum_names(), ", ", " or "))
      ->check(CLI::IsMember(ocean::model::spectrum_names()))
      ->capture_default_str();
  app.add_option("--spreading", o.spreading, "JONSWAP spreading: " + join_names(ocean::model::spreading_names(), ", ", " or "))
      ->check(CLI::IsMember(ocean::model::spreading_names()))
      ->capture_default_str();
  app.add_option("--wind", s.wind_speed_mps, "wind speed U10 in m/s")->capture_default_str();
  app.add_option("--wind-dir", s.wind_dir_deg, "direction the wind blows towards, degrees from +x to +z");
  app.add_option("--fetch", s.fetch_m, "JONSWAP fetch in metres")->capture_default_str();
  app.add_option("--amplitude", s.amplitude, "scale on the spectrum's energy")->capture_default_str();
  app.add_option("--depth", s.depth_m, "water depth in metres (inf = deep)");
  app.add_option("--small-wave", s.small_wave_m, "small-wave suppression length l in metres (0 = grid default)");
  CLI11_PARSE(app, argc, argv);

  if (o.size) s.size_x = s.size_z = o.size;
  if (o.patch_m) s.patch_x_m = s.patch_z_m = o.patch_m;
  s.spectrum = *ocean::model::spectrum_from_name(o.spectrum);  // IsMember checked the names
  s.spreading = *ocean::model::spreading_from_name(o.spreading);
  s.choppiness = o.choppy ? o.lambda : 0.0;

  try {
    ocean::sim::Ocean ocean(s);
    const FrameRequest request{!o.no_slopes, o.choppy};
    if (o.hash && !o.json && !o.summary) {
      const Tick tick = run_tick(ocean, o, request, 1);
      std::printf("%016" PRIx64 "\n", ocean::sim::frame_hash(tick.frame));
      return 0;
    }
    const Tick tick = run_tick(ocean, o, request, 10);
    if (o.json)
      print_json(ocean, o, tick);
    else
      print_summary(ocean, o, tick);
  } catch (const ocean::model::ParamError& e) {
    std::fprintf(stderr, "ocean-simdump: %s\n", e.what());
    return 2;
  }
  return 0;
}
