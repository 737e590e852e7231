// The wake lattice (codec version 6): the server's wake of 8 vessels on circuits (EpochWake, 10 s
// epochs), streamed beside a band of the sea at a lag of 3 ticks, decodes bit for bit as the
// encoder reconstructs it and within half a step of the truth in every channel. A decoder told the
// tracks predicts the hulls' forcing and the epochs' drops, so the wake costs next to nothing and a
// key for a viewer joining mid-run carries no wake; one not told gets the forcing as corrections.
// (Lag 1, keys and a change of scene: the mobile_wake vector.)
#include "cascade_frame.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "ocean.hpp"
#include "vessel_track.hpp"
#include "epoch_wake.hpp"
#include "wake_field.hpp"
#include "wake_frame.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;
namespace sim = ocean::sim;

namespace wake_test {

constexpr double kRegion = 512.0;

StreamConfig wake_stream(bool choppy) {
  StreamConfig c;
  c.grid = 64;
  c.rate_hz = 30;
  c.normals = true;
  c.choppy = choppy;
  c.wake = {64, kRegion, -256.0, -256.0, 0.05, 1e-6, 300};  // epochs of 10 s: the test crosses two
  return c;
}

// n vessels on square circuits round the world's origin (the wake region's middle) at 5..9 m/s.
std::vector<model::VesselTrack> fleet(int n) {
  std::vector<model::VesselTrack> out;
  for (int v = 0; v < n; ++v) {
    const double half = 60.0 + 15.0 * v, speed = 5.0 + 4.0 * v / std::max(1, n - 1);
    const double c = 0.0, leg = 2 * half / speed;
    model::VesselTrack t;
    t.id = static_cast<std::uint32_t>(v + 1);
    t.hull = {24.0, 6.0, 1.5};
    t.repeat = true;
    t.points = {{0, c - half, c - half}, {leg, c + half, c - half}, {2 * leg, c + half, c + half},
                {3 * leg, c - half, c + half}, {4 * leg, c - half, c - half}};
    out.push_back(t);
  }
  return out;
}

// The sea's band and the server's wake (EpochWake: two epochs of 10 s, so the test crosses the
// drop of an old epoch's waves twice).
struct Truth {
  sim::Ocean ocean;
  sim::EpochWake wake;
  sim::WakeSampler sampler;
  double choppiness;

  Truth(const model::SceneParams& scene, const StreamConfig& c, std::vector<model::VesselTrack> vessels)
      : ocean(scene),
        wake(sim::WakeRegion{kRegion, 128, 9.81, scene.depth_m, c.wake.decay_per_s, c.wake.viscosity_m2ps}, c.wake.origin_x_m,
             c.wake.origin_z_m, std::move(vessels), c.rate_hz, c.wake.epoch_ticks),
        choppiness(scene.choppiness) {}

  sim::Frame at(std::uint64_t tick, const StreamConfig& c) {
    wake.advance_to(static_cast<std::int64_t>(tick));
    sim::Frame f, w;
    ocean.evaluate_band(static_cast<double>(tick) * c.dt_s(), c.grid, c.grid, f, {true, c.choppy});
    sampler.sample(wake.fields(), c.wake.grid, {true, c.choppy}, choppiness, w);
    sim::append_cascade_frame(f, w);  // the wake lattice's samples follow the sea's, as a cascade's would
    return f;
  }
};

TruthView wake_view(const sim::Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz};
}

double wake_worst(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(static_cast<double>(a[i]) - b[i]));
  return m;
}

model::SceneParams calm() {
  model::SceneParams s;
  s.size_x = s.size_z = 64;
  s.wind_speed_mps = 6.0;
  s.choppiness = 0.8;
  return s;
}

struct StreamFigures {
  double bytes_per_frame = 0;  // over the last 10 of 20 s
  double err_h = 0, err_s = 0, err_d = 0, err_dd = 0;
  bool bitwise = true;
  double wake_peak = 0;
  std::size_t late_key_bytes = 0;  // a key for a decoder that joins at 15 s
  double late_key_err = 0;
};

// 20 s of 8 vessels' wakes beside the sea, every delta at a lag of 3 ticks; `told`: the encoder
// and decoder know the vessels' tracks (else the hulls' forcing comes as corrections).
StreamFigures stream_wakes(bool choppy, bool told) {
  const StreamConfig config = wake_stream(choppy);
  REQUIRE(validate(config).empty());
  const model::SceneParams scene = calm();
  Truth truth(scene, config, fleet(8));
  Encoder encoder(config);
  Decoder decoder(config);
  encoder.set_scene(0, 1, scene);
  decoder.add_scene(0, 1, scene);
  if (told) {
    encoder.set_vessels(fleet(8));
    decoder.set_vessels(fleet(8));
  }
  const std::uint64_t last = 600;
  std::map<std::uint64_t, StateId> ids;
  StreamFigures out;
  std::size_t bytes = 0, frames = 0;
  std::vector<double> decode_ms;  // informative: a decoder's time per frame (CODEC.md 11 quotes it)
  for (std::uint64_t tick = 0; tick <= last; ++tick) {
    const sim::Frame f = truth.at(tick, config);
    encoder.add_truth(tick, wake_view(f));
    const auto encoded = tick == 0 ? encoder.encode_key(tick) : encoder.encode_delta(tick, ids.at(tick < 3 ? 0 : tick - 3));
    ids[tick] = encoded->id;
    const auto t0 = std::chrono::steady_clock::now();
    for (const Chunk& chunk : encoded->chunks) REQUIRE(decoder.accept(view(chunk)) == ChunkError::ok);
    const ReconstructedFrame* shown = decoder.latest();
    if (tick > last - 300)
      decode_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    REQUIRE(shown);
    REQUIRE(shown->tick == tick);
    out.bitwise = out.bitwise && shown->height == encoded->reconstruction.height &&
                  shown->slope_x == encoded->reconstruction.slope_x && shown->jacobian == encoded->reconstruction.jacobian;
    out.err_h = std::max(out.err_h, wake_worst(shown->height, f.height));
    out.err_s = std::max({out.err_s, wake_worst(shown->slope_x, f.slope_x), wake_worst(shown->slope_z, f.slope_z)});
    if (choppy) {
      out.err_d = std::max({out.err_d, wake_worst(shown->disp_x, f.disp_x), wake_worst(shown->disp_z, f.disp_z)});
      out.err_dd = std::max({out.err_dd, wake_worst(shown->disp_xx, f.disp_xx), wake_worst(shown->disp_xz, f.disp_xz)});
    }
    if (tick > last - 300) {
      bytes += encoded->stats.payload_bytes;
      ++frames;
    }
    if (tick == 450) {  // a viewer that joins now: its key's wake comes from the tracks when told
      Decoder late(config);
      late.add_scene(0, 1, scene);
      if (told) late.set_vessels(fleet(8));
      const auto key = encoder.encode_key(tick);
      for (const Chunk& chunk : key->chunks) REQUIRE(late.accept(view(chunk)) == ChunkError::ok);
      out.late_key_bytes = key->stats.payload_bytes;
      out.late_key_err = wake_worst(late.latest()->height, f.height);
    }
    for (std::size_t i = 64 * 64; i < f.height.size(); ++i)
      out.wake_peak = std::max(out.wake_peak, std::fabs(static_cast<double>(f.height[i])));
  }
  out.bytes_per_frame = static_cast<double>(bytes) / frames;
  std::nth_element(decode_ms.begin(), decode_ms.begin() + decode_ms.size() / 2, decode_ms.end());
  std::printf("  decode per frame, median of the last 300: %.3f ms\n", decode_ms[decode_ms.size() / 2]);
  std::printf("wake stream (%s, 8 vessels, 64 x 64 wake over %g m, tracks %s): %.1f payload bytes per frame "
              "(10-20 s), a key at 15 s %zu bytes; wake peak %.3f m; errors h %.2g s %.2g d %.2g dd %.2g\n",
              choppy ? "choppy" : "plain", kRegion, told ? "told" : "not told", out.bytes_per_frame, out.late_key_bytes,
              out.wake_peak, out.err_h, out.err_s, out.err_d, out.err_dd);
  return out;
}

}  // namespace wake_test
using namespace wake_test;

TEST_CASE("eight vessels' wakes stream within half a step, bit for bit, at a lag of three ticks", "[wake]") {
  for (const bool choppy : {false, true}) {
    const StreamConfig config = wake_stream(choppy);
    const StreamFigures told = stream_wakes(choppy, true), untold = stream_wakes(choppy, false);
    for (const StreamFigures& f : {told, untold}) {
      CHECK(f.bitwise);
      CHECK(f.wake_peak > 0.1);
      CHECK(f.err_h <= 0.5 * config.height_step_m);
      CHECK(f.err_s <= 0.5 * config.slope_step);
      CHECK(f.err_d <= 0.5 * config.disp_step_m);
      CHECK(f.err_dd <= 0.5 * config.slope_step);
    }
    // The decoder that knows the tracks predicts the hulls' forcing: the wake costs next to
    // nothing beside the sea's own bytes, and a viewer joining mid-run computes the wake of the
    // last two epochs itself, so its key carries no wake either.
    CHECK(told.bytes_per_frame < 0.1 * untold.bytes_per_frame);
    CHECK(told.late_key_bytes < 0.05 * untold.late_key_bytes);
    CHECK(told.late_key_err <= 0.5 * config.height_step_m);
  }
}

TEST_CASE("a fleet changed mid-stream (a vessel command) streams as if it had always been the fleet", "[wake]") {
  // Vessel 1 of the circuits turns away at tick 400 (its circuit ends there, a straight leg east
  // starts from where it was) and an object splashes for a second: the server's sim, the encoder
  // and a watching decoder take the new fleet 30 ticks ahead; a decoder that joins at tick 500
  // knows only the new fleet. Epochs of 10 s: tick 600 drops the epoch that held the old circuit.
  const StreamConfig config = wake_stream(false);
  const std::vector<model::VesselTrack> before = fleet(3);
  constexpr std::uint64_t kChange = 400;
  const double change_s = kChange * config.dt_s();
  std::vector<model::VesselTrack> after = before;
  const model::HullPose there = model::pose_at(after[0], change_s);
  after[0].presence = {0.0, change_s, 0.0};
  model::VesselTrack turned = after[0];
  turned.repeat = false;
  turned.presence = {change_s, std::numeric_limits<double>::infinity(), 0.0};
  turned.points = {{0.0, there.x_m, there.z_m}, {change_s, there.x_m, there.z_m}, {change_s + 20.0, there.x_m + 140.0, there.z_m}};
  after.push_back(turned);
  model::VesselTrack object;
  object.id = 40;
  object.hull = {4.0, 4.0, 2.0};
  object.points = {{0.0, -30.0, 40.0}};
  object.presence = {change_s + 0.5, 1.0, 0.0};
  after.push_back(object);

  const model::SceneParams scene = calm();
  Truth truth(scene, config, before);
  Encoder encoder(config);
  Decoder watching(config), joining(config);
  encoder.set_scene(0, 0, scene);
  watching.add_scene(0, 0, scene);
  joining.add_scene(0, 0, scene);
  encoder.set_vessels(before);
  watching.set_vessels(before);
  joining.set_vessels(after);
  std::size_t bytes_after = 0, frames_after = 0;
  bool bitwise = true;
  double worst = 0.0;
  StateId previous{};
  for (std::uint64_t tick = 1; tick <= 700; ++tick) {
    if (tick == kChange - 30) {
      truth.wake.set_tracks(after, static_cast<std::int64_t>(kChange));
      encoder.set_vessels(after, kChange);
      watching.set_vessels(after, kChange);
    }
    const sim::Frame f = truth.at(tick, config);
    encoder.add_truth(tick, wake_view(f));
    if (tick == 1) {
      const auto key = encoder.encode_key(tick);
      previous = key->id;
      for (const Chunk& c : key->chunks) REQUIRE(watching.accept(view(c)) == ChunkError::ok);
      continue;
    }
    const auto delta = encoder.encode_delta(tick, previous);
    previous = delta->id;
    for (const Chunk& c : delta->chunks) REQUIRE(watching.accept(view(c)) == ChunkError::ok);
    const ReconstructedFrame* shown = watching.latest();
    REQUIRE(shown);
    bitwise = bitwise && shown->height == delta->reconstruction.height;
    worst = std::max(worst, wake_worst(shown->height, f.height));
    if (tick > kChange) {
      for (const Chunk& c : delta->chunks) bytes_after += c.payload.size();
      ++frames_after;
    }
    if (tick == 500) {
      const auto key = encoder.encode_key(tick);
      for (const Chunk& c : key->chunks) REQUIRE(joining.accept(view(c)) == ChunkError::ok);
      REQUIRE(joining.latest());
      CHECK(joining.latest()->height == key->reconstruction.height);
    }
  }
  const double per_frame = static_cast<double>(bytes_after) / static_cast<double>(frames_after);
  std::printf("a fleet changed at tick 400: %.1f payload bytes a frame after it, worst error %.2g m\n", per_frame, worst);
  CHECK(bitwise);
  CHECK(worst <= 0.5 * config.height_step_m);
  // The encoder predicts the new fleet as the sim forces it: no corrections after the change.
  CHECK(per_frame < 6.0);
}

TEST_CASE("the wake follows a change of depth as the decoders' recurrence does", "[wake]") {
  // The tide goes out at tick 300: 12 m of water from there on (announced ahead). The server's sim
  // steps the wake with the depth in force at each tick, so the decoder's prediction, which
  // follows the scene in force, needs no correction; a server (or replica) started after the
  // change computes the same wake from the schedule.
  const StreamConfig config = wake_stream(false);
  const std::vector<model::VesselTrack> vessels = fleet(3);
  constexpr std::uint64_t kChange = 300;
  const model::SceneParams deep = calm();
  model::SceneParams shallow = deep;
  shallow.depth_m = 12.0;
  Truth truth(deep, config, vessels);
  truth.wake.set_depth(shallow.depth_m, static_cast<std::int64_t>(kChange));
  Truth late(deep, config, vessels);  // a second server, told the schedule from the start
  late.wake.set_depth(shallow.depth_m, static_cast<std::int64_t>(kChange));
  Encoder encoder(config);
  Decoder decoder(config);
  encoder.set_scene(0, 0, deep);
  encoder.set_scene(kChange, 1, shallow);
  decoder.add_scene(0, 0, deep);
  decoder.add_scene(kChange, 1, shallow);
  encoder.set_vessels(vessels);
  decoder.set_vessels(vessels);
  std::size_t bytes_after = 0, frames_after = 0;
  StateId previous{};
  for (std::uint64_t tick = 1; tick <= 500; ++tick) {
    if (tick == kChange) truth.ocean = sim::Ocean(shallow);  // the sea's own band follows too
    const sim::Frame f = truth.at(tick, config);
    encoder.add_truth(tick, wake_view(f));
    const auto encoded = tick == 1 ? encoder.encode_key(tick) : encoder.encode_delta(tick, previous);
    previous = encoded->id;
    for (const Chunk& c : encoded->chunks) REQUIRE(decoder.accept(view(c)) == ChunkError::ok);
    if (tick > kChange + 1) {
      for (const Chunk& c : encoded->chunks) bytes_after += c.payload.size();
      ++frames_after;
    }
  }
  const sim::Frame restarted = late.at(500, config), stepped = truth.at(500, config);
  const double per_frame = static_cast<double>(bytes_after) / static_cast<double>(frames_after);
  std::printf("a change of depth at tick 300: %.1f payload bytes a frame after it\n", per_frame);
  CHECK(per_frame < 6.0);
  const std::size_t sea = static_cast<std::size_t>(config.grid) * config.grid;
  CHECK(std::vector<float>(restarted.height.begin() + sea, restarted.height.end()) ==
        std::vector<float>(stepped.height.begin() + sea, stepped.height.end()));
}
