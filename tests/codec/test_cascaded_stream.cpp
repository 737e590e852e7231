// Cascaded streams (codec version 5): one stream of several lattices, each a cascade of the scene
// (common/cascade.hpp), their states, fields and items one after the other. A storm's cascades
// stream from the band-limited sims bit for bit as the encoder reconstructs them, every channel
// within half its step, with a modeled key and no more corrections than one lattice's; a cascaded
// chunk is refused by a stream without cascades and the reverse.
#include "cascade_set.hpp"
#include "chunk_format.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <span>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;

namespace {

model::SceneParams storm() {
  model::SceneParams s;
  s.spectrum = model::SpectrumKind::jonswap;
  s.wind_speed_mps = 20.0;
  s.wind_dir_deg = 30.0;
  s.choppiness = 1.2;
  s.seed = 11;
  return s;
}

// A 256 m tile of the waves under 64 m and a 2048 m cascade of the longer ones.
StreamConfig cascaded_stream() {
  StreamConfig c;
  c.grid = 64;
  c.rate_hz = 30;
  c.normals = true;
  c.choppy = true;
  c.cascades = {{1, 64, {4, 0}}, {8, 64, {0, 32}}};
  return c;
}

// The sims' frames of every cascade at time t, one after the other as the stream's fields.
ocean::sim::Frame truth_at(ocean::sim::CascadeSet& cascades, double t) {
  ocean::sim::Frame f;
  cascades.evaluate(t, f, {true, true});
  return f;
}

TruthView view_of(const ocean::sim::Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz};
}

double worst(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(static_cast<double>(a[i]) - b[i]));
  return m;
}

}  // namespace

TEST_CASE("a storm's cascades stream as one stream within half a step of their sims", "[cascade]") {
  const StreamConfig config = cascaded_stream();
  REQUIRE(validate(config).empty());
  CHECK(config.samples() == 2u * 64 * 64);
  const model::SceneParams scene = storm();
  ocean::sim::CascadeSet sims(scene, config.cascades);
  Encoder encoder(config);
  Decoder decoder(config);
  encoder.set_scene(0, 1, scene);
  decoder.add_scene(0, 1, scene);

  const std::uint64_t first = 90'000, last = first + 30;
  double err_h = 0, err_s = 0, err_d = 0, err_dd = 0;
  std::size_t key_bytes = 0, delta_bytes = 0, corrections = 0;
  bool bitwise = true;
  std::map<std::uint64_t, StateId> ids;
  for (std::uint64_t tick = first; tick <= last; ++tick) {
    const ocean::sim::Frame truth = truth_at(sims, tick_time_s(static_cast<std::int64_t>(tick), config.rate_hz));
    encoder.add_truth(tick, view_of(truth));
    // Lag 1, and every fifth frame lag 3 from an older state.
    const bool older = tick >= first + 3 && tick % 5 == 0;
    const auto encoded = tick == first ? encoder.encode_key(tick) : encoder.encode_delta(tick, ids.at(tick - (older ? 3 : 1)));
    ids[tick] = encoded->id;
    for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
    const ReconstructedFrame* shown = decoder.latest();
    REQUIRE(shown);
    REQUIRE(shown->complete);
    REQUIRE(shown->tick == tick);
    bitwise = bitwise && shown->height == encoded->reconstruction.height && shown->disp_xz == encoded->reconstruction.disp_xz &&
              shown->jacobian == encoded->reconstruction.jacobian;
    err_h = std::max(err_h, worst(shown->height, truth.height));
    err_s = std::max({err_s, worst(shown->slope_x, truth.slope_x), worst(shown->slope_z, truth.slope_z)});
    err_d = std::max({err_d, worst(shown->disp_x, truth.disp_x), worst(shown->disp_z, truth.disp_z)});
    err_dd = std::max({err_dd, worst(shown->disp_xx, truth.disp_xx), worst(shown->disp_zz, truth.disp_zz),
                       worst(shown->disp_xz, truth.disp_xz)});
    (tick == first ? key_bytes : delta_bytes) += encoded->stats.payload_bytes;
    corrections += encoded->stats.corrections_height + encoded->stats.corrections_slope + encoded->stats.corrections_choppy;
  }
  std::printf("cascaded stream (256 m + 2048 m at 64 x 64): key %zu bytes, deltas %zu bytes for 30 frames, %zu "
              "corrections; errors h %.2g s %.2g d %.2g dd %.2g\n",
              key_bytes, delta_bytes, corrections, err_h, err_s, err_d, err_dd);
  CHECK(bitwise);
  CHECK(err_h <= 0.5 * config.height_step_m);
  CHECK(err_s <= 0.5 * config.slope_step);
  CHECK(err_d <= 0.5 * config.disp_step_m);
  CHECK(err_dd <= 0.5 * config.slope_step);
  CHECK(key_bytes < 64);  // modeled: the scene model knows both cascades' waves
  CHECK(corrections <= 30 * 8 * config.samples() / 1000);
}

// An explicit key numbers every lattice's key modes in turn, at shifts the encoder picks for the
// smallest lattice (CODEC.md 7.3, 7.8): lattices of different sizes, and a truth the scene model
// misses (another seed), so the key is explicit.
TEST_CASE("an explicit key of lattices of different sizes decodes bit for bit within half a step", "[cascade]") {
  StreamConfig config = cascaded_stream();
  config.cascades = {{1, 64, {4, 0}}, {8, 32, {0, 16}}};
  REQUIRE(validate(config).empty());
  const model::SceneParams announced = storm();
  model::SceneParams truth_scene = announced;
  truth_scene.seed = 12;
  ocean::sim::CascadeSet sims(truth_scene, config.cascades);
  Encoder encoder(config);
  Decoder decoder(config);
  encoder.set_scene(0, 1, announced);
  decoder.add_scene(0, 1, announced);

  const std::uint64_t first = 3'000;
  std::optional<StateId> previous;
  for (std::uint64_t tick = first - 1; tick <= first + 4; ++tick) {
    const ocean::sim::Frame truth = truth_at(sims, tick_time_s(static_cast<std::int64_t>(tick), config.rate_hz));
    encoder.add_truth(tick, view_of(truth));
    if (tick < first) continue;  // an explicit key's velocities come from the tick before
    const auto encoded = tick == first ? encoder.encode_key(tick) : encoder.encode_delta(tick, *previous);
    previous = encoded->id;
    if (tick == first) {
      ChunkHeader h;
      std::span<const std::uint8_t> body;
      REQUIRE(parse_payload(view(encoded->chunks.at(0)), 65536, config.grid_log2(), h, body) == ChunkError::ok);
      CHECK_FALSE(h.modeled);
      CHECK(h.cascaded);
    }
    for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
    const ReconstructedFrame* shown = decoder.latest();
    REQUIRE(shown);
    REQUIRE(shown->complete);
    REQUIRE(shown->tick == tick);
    INFO("tick " << tick);
    CHECK(shown->height == encoded->reconstruction.height);
    CHECK(shown->slope_z == encoded->reconstruction.slope_z);
    CHECK(shown->disp_xz == encoded->reconstruction.disp_xz);
    CHECK(shown->jacobian == encoded->reconstruction.jacobian);
    CHECK(worst(shown->height, truth.height) <= 0.5 * config.height_step_m);
    CHECK(worst(shown->slope_x, truth.slope_x) <= 0.5 * config.slope_step);
    CHECK(worst(shown->disp_x, truth.disp_x) <= 0.5 * config.disp_step_m);
    CHECK(worst(shown->disp_zz, truth.disp_zz) <= 0.5 * config.slope_step);
  }
}

TEST_CASE("cascaded chunks and plain streams refuse each other", "[cascade]") {
  const StreamConfig cascaded = cascaded_stream();
  StreamConfig plain = cascaded;
  plain.cascades.clear();
  const model::SceneParams scene = storm();
  ocean::sim::CascadeSet sims(scene, cascaded.cascades);
  Encoder encoder(cascaded);
  encoder.set_scene(0, 1, scene);
  const ocean::sim::Frame truth = truth_at(sims, 1.0);
  encoder.add_truth(30, view_of(truth));
  const auto key = encoder.encode_key(30);
  Decoder other(plain);
  other.add_scene(0, 1, scene);
  CHECK(other.accept(view(key->chunks.at(0))) == ChunkError::wrong_dimensions);

  ocean::sim::Ocean one(scene);
  ocean::sim::Frame f;
  one.evaluate_band(1.0, 64, 64, f, {true, true});
  Encoder plain_encoder(plain);
  plain_encoder.set_scene(0, 1, scene);
  plain_encoder.add_truth(30, TruthView{f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz});
  Decoder cascaded_decoder(cascaded);
  cascaded_decoder.add_scene(0, 1, scene);
  CHECK(cascaded_decoder.accept(view(plain_encoder.encode_key(30)->chunks.at(0))) == ChunkError::wrong_dimensions);
  // A truth of one lattice's samples is refused by name.
  CHECK_THROWS_WITH(encoder.add_truth(31, TruthView{f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx,
                                                    f.disp_zz, f.disp_xz}),
                    Catch::Contains("lattices need 8192"));
}

TEST_CASE("stream configs name what is wrong with their cascades", "[cascade]") {
  StreamConfig c = cascaded_stream();
  c.grid = 128;
  CHECK_THAT(validate(c), Catch::Contains("first cascade's"));
  c = cascaded_stream();
  c.cascades[1].grid = 512;
  CHECK_THAT(validate(c), Catch::Contains("cascade 1: grid = 512"));
  c = cascaded_stream();
  c.cascades.resize(5, c.cascades[1]);
  CHECK_THAT(validate(c), Catch::Contains("at most 4"));
  c = cascaded_stream();
  c.cascades[1].band = {9, 3};
  CHECK_THAT(validate(c), Catch::Contains("cascade 1: band"));
}
