// Choppy streams (codec version 3) against the sim: the horizontal displacement and its three
// derivatives are predicted from the height state like the slopes, so a storm costs (almost) no
// corrections after its modeled key; every channel of every frame is within half its step of the
// sim, and the Jacobian the decoder forms from them matches the sim's where foam is decided. A
// change of choppiness is a scene change: no key, and the next frames already show the new lambda.
#include "cascade_scene.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "ocean.hpp"
#include "scene_model.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;

namespace {

model::SceneParams storm(double choppiness) {
  model::SceneParams s;
  s.spectrum = model::SpectrumKind::jonswap;
  s.wind_speed_mps = 20.0;
  s.wind_dir_deg = 30.0;
  s.choppiness = choppiness;
  s.seed = 7;
  return s;
}

StreamConfig choppy_stream(int grid) {
  StreamConfig c;  // desktop-choppy's steps
  c.grid = static_cast<std::uint16_t>(grid);
  c.rate_hz = 30;
  c.normals = true;
  c.choppy = true;
  return c;
}

struct ChannelErrors {
  double height = 0, slope = 0, disp = 0, derivative = 0;
  double jacobian_excess = 0;  // largest |J - J_sim| beyond what the inputs' bounds allow
  float min_jacobian = 1.0f;
  bool bitwise = true;
};

void compare(const ReconstructedFrame& got, const ocean::sim::Frame& truth, const StreamConfig& c, ChannelErrors& e) {
  const auto worst = [](const std::vector<float>& a, const std::vector<float>& b) {
    REQUIRE(a.size() == b.size());
    double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(static_cast<double>(a[i]) - b[i]));
    return m;
  };
  e.height = std::max(e.height, worst(got.height, truth.height));
  e.slope = std::max({e.slope, worst(got.slope_x, truth.slope_x), worst(got.slope_z, truth.slope_z)});
  e.disp = std::max({e.disp, worst(got.disp_x, truth.disp_x), worst(got.disp_z, truth.disp_z)});
  e.derivative = std::max({e.derivative, worst(got.disp_xx, truth.disp_xx), worst(got.disp_zz, truth.disp_zz),
                           worst(got.disp_xz, truth.disp_xz)});
  // J = (1 + xx)(1 + zz) - xz^2 with each input off by at most h = slope_step / 2.
  const double h = 0.5 * static_cast<double>(c.slope_step);
  REQUIRE(got.jacobian.size() == truth.jacobian.size());
  for (std::size_t i = 0; i < got.jacobian.size(); ++i) {
    const double a = std::fabs(1.0 + truth.disp_xx[i]), b = std::fabs(1.0 + truth.disp_zz[i]);
    const double bound = h * (a + b + h) + h * (2.0 * std::fabs(truth.disp_xz[i]) + h) + 1e-5;
    e.jacobian_excess = std::max(e.jacobian_excess, std::fabs(static_cast<double>(got.jacobian[i]) - truth.jacobian[i]) - bound);
    e.min_jacobian = std::min(e.min_jacobian, got.jacobian[i]);
  }
}

// Streams ticks [first, last] with lag-1 deltas after a key; the scene of each tick comes from
// `scene_at`, announced to both sides before its frames.
struct Run {
  ChannelErrors errors;
  std::size_t choppy_corrections = 0, other_corrections = 0, choppy_samples = 0, delta_payload = 0, key_payload = 0;
  int deltas = 0;
};

template <typename SceneAt>
Run stream(const StreamConfig& config, std::uint64_t first, std::uint64_t last, std::uint64_t change_at, SceneAt scene_at) {
  Encoder encoder(config);
  Decoder decoder(config);
  encoder.set_scene(0, 1, scene_at(0));
  decoder.add_scene(0, 1, scene_at(0));
  if (change_at != 0) {
    encoder.set_scene(change_at, 2, scene_at(change_at));
    decoder.add_scene(change_at, 2, scene_at(change_at));
  }
  ocean::sim::Ocean before(scene_at(0));
  ocean::sim::Ocean after(scene_at(change_at));
  Run run;
  ocean::sim::Frame frame;
  StateId previous{};
  for (std::uint64_t tick = first; tick <= last; ++tick) {
    ocean::sim::Ocean& sim = change_at != 0 && tick >= change_at ? after : before;
    sim.evaluate_band(tick_time_s(static_cast<std::int64_t>(tick), config.rate_hz), config.grid, config.grid, frame,
                      ocean::sim::FrameRequest{true, true});
    encoder.add_truth(tick, TruthView{frame.height, frame.slope_x, frame.slope_z, frame.disp_x, frame.disp_z,
                                      frame.disp_xx, frame.disp_zz, frame.disp_xz});
    const auto encoded = tick == first ? encoder.encode_key(tick) : encoder.encode_delta(tick, previous);
    previous = encoded->id;
    for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
    const ReconstructedFrame* shown = decoder.latest();
    REQUIRE(shown);
    REQUIRE(shown->complete);
    run.errors.bitwise = run.errors.bitwise && shown->height == encoded->reconstruction.height &&
                         shown->disp_x == encoded->reconstruction.disp_x &&
                         shown->disp_xz == encoded->reconstruction.disp_xz &&
                         shown->jacobian == encoded->reconstruction.jacobian;
    compare(*shown, frame, config, run.errors);
    if (tick == first) run.key_payload = encoded->stats.payload_bytes;
    if (tick != first) {
      ++run.deltas;
      run.choppy_corrections += encoded->stats.corrections_choppy;
      run.other_corrections += encoded->stats.corrections_height + encoded->stats.corrections_slope;
      run.choppy_samples += 5 * frame.height.size();
      run.delta_payload += encoded->stats.payload_bytes;
    }
  }
  return run;
}

void check_bounds(const Run& run, const StreamConfig& c) {
  CHECK(run.errors.bitwise);
  CHECK(run.errors.height <= 0.5 * c.height_step_m);
  CHECK(run.errors.slope <= 0.5 * c.slope_step);
  CHECK(run.errors.disp <= 0.5 * c.disp_step_m);
  CHECK(run.errors.derivative <= 0.5 * c.slope_step);
  CHECK(run.errors.jacobian_excess <= 0.0);
}

}  // namespace

TEST_CASE("a storm's choppy channels stream within half a step of the sim, predicted like the slopes", "[choppy]") {
  for (const int grid : {64, 256}) {
    const StreamConfig config = choppy_stream(grid);
    const std::uint64_t first = 1'000'000'000, last = first + (grid == 64 ? 45 : 8);
    const Run run = stream(config, first, last, 0, [](std::uint64_t) { return storm(1.2); });
    std::printf("choppy %d: deltas %d, corrections choppy %zu of %zu samples, other %zu, delta bytes %zu, "
                "errors h %.2g s %.2g d %.2g dd %.2g, min J %.3f\n",
                grid, run.deltas, run.choppy_corrections, run.choppy_samples, run.other_corrections, run.delta_payload,
                run.errors.height, run.errors.slope, run.errors.disp, run.errors.derivative, run.errors.min_jacobian);
    check_bounds(run, config);
    // The storm folds: the full band compresses the surface far below a calm sea's J of about 1.
    if (grid == 256) CHECK(run.errors.min_jacobian < 0.6f);
    // The prediction is the sim's own linear map of the heights: corrections are the exception.
    CHECK(static_cast<double>(run.choppy_corrections) <= 1e-3 * static_cast<double>(run.choppy_samples));
  }
}

TEST_CASE("each cascade of a storm streams like a scene of its own", "[choppy][cascade]") {
  // The scene model knows a cascade's lattice, band and draws: its key is modeled like a plain
  // scene's, and its frames are the band-limited sim's within half a step.
  const StreamConfig plain = choppy_stream(64);
  const std::uint64_t first = 3000, last = first + 20;
  const Run base = stream(plain, first, last, 0, [](std::uint64_t) { return storm(1.2); });
  for (const auto& [cascade, index] : {std::pair{ocean::Cascade{8, 64, {0, 32}}, 1}, std::pair{ocean::Cascade{1, 64, {4, 0}}, 0}}) {
    const model::SceneParams scene = model::cascade_scene(storm(1.2), cascade, index);
    StreamConfig config = plain;
    config.patch_x_m = scene.patch_x_m;
    config.patch_z_m = scene.patch_z_m;
    const Run run = stream(config, first, last, 0, [&](std::uint64_t) { return scene; });
    std::printf("cascade %d (%.0f m, band [%d, %d)): key %zu bytes (plain storm %zu), delta bytes %zu (%zu), "
                "corrections %zu + %zu choppy\n",
                index, scene.patch_x_m, cascade.band.min_cycles, cascade.band.max_cycles, run.key_payload,
                base.key_payload, run.delta_payload, base.delta_payload, run.other_corrections, run.choppy_corrections);
    INFO("cascade " << index);
    check_bounds(run, config);
    CHECK(run.key_payload <= 2 * base.key_payload);
    CHECK(run.delta_payload <= 2 * base.delta_payload);
  }
}

TEST_CASE("a change of choppiness is a scene change: no key, and the new lambda from its tick on", "[choppy]") {
  const StreamConfig config = choppy_stream(64);
  const std::uint64_t first = 5000, change = 5010, last = 5025;
  for (const double to : {0.5, 0.0}) {
    const Run run = stream(config, first, last, change, [&](std::uint64_t tick) { return storm(tick >= change ? to : 1.2); });
    check_bounds(run, config);
    CHECK(static_cast<double>(run.choppy_corrections) <= 1e-3 * static_cast<double>(run.choppy_samples));
  }
}

TEST_CASE("a choppy chunk is refused by a stream without choppy channels, and the reverse", "[choppy]") {
  StreamConfig choppy = choppy_stream(32), plain = choppy_stream(32);
  plain.choppy = false;
  for (const auto& [from, to] : {std::pair{choppy, plain}, std::pair{plain, choppy}}) {
    Encoder encoder(from);
    encoder.set_scene(0, 0, storm(1.0));
    Decoder decoder(to);
    decoder.add_scene(0, 0, storm(1.0));
    const std::size_t nn = 32 * 32;
    std::vector<float> zero(nn, 0.0f);
    TruthView truth{zero, zero, zero};
    if (from.choppy) truth = TruthView{zero, zero, zero, zero, zero, zero, zero, zero};
    encoder.add_truth(10, truth);
    const auto key = encoder.encode_key(10);
    CHECK(decoder.accept(view(key->chunks.front())) == ChunkError::wrong_dimensions);
  }
}

TEST_CASE("a choppy encoder names the missing channels instead of streaming without them", "[choppy]") {
  Encoder encoder(choppy_stream(32));
  std::vector<float> zero(32 * 32, 0.0f);
  try {
    encoder.add_truth(1, TruthView{zero, zero, zero});
    FAIL("add_truth accepted a choppy frame without displacement");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("displacement") != std::string::npos);
  }
}
