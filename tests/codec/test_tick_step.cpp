// A stream at half the server's tick rate (every 2nd tick): with tick_rate_hz set, the predictor
// advances by real tick steps, decodes bit-exactly, and needs fewer bytes than the wrong step.
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

using namespace ocean::codec;
using namespace ocean::codec::test;
using ocean::codec::test::SyntheticFrame;
using ocean::codec::test::SyntheticOcean;

namespace {

struct StepRun {
  std::size_t delta_bytes = 0;
  bool bitwise = true;
};

// The truth is sampled at tick / 30 s; the stream carries ticks 1, 3, 5, ... (rate 15 Hz).
StepRun run_every_second_tick(std::uint16_t tick_rate_hz) {
  const SyntheticOcean ocean(32, 64.0, 24, 5);
  StreamConfig config;
  config.grid = 32;
  config.patch_x_m = config.patch_z_m = 64.0;
  config.rate_hz = 15;
  config.tick_rate_hz = tick_rate_hz;
  Encoder encoder = test_encoder(config);
  Decoder decoder = test_decoder(config);
  StepRun run;
  StateId previous{};
  for (std::uint32_t tick = 0; tick <= 41; ++tick) {
    const SyntheticFrame truth = ocean.at(tick / 30.0);
    encoder.add_truth(tick, TruthView{truth.height, truth.slope_x, truth.slope_z});
    if (tick % 2 == 0) continue;
    auto frame = tick == 1 ? encoder.encode_key(tick) : encoder.encode_delta(tick, previous);
    previous = frame->id;
    for (const Chunk& chunk : frame->chunks) {
      REQUIRE(decoder.accept(chunk) == ChunkError::ok);
      if (!frame->key) run.delta_bytes += chunk.payload.size();
    }
    const ReconstructedFrame* shown = decoder.latest();
    REQUIRE(shown != nullptr);
    run.bitwise = run.bitwise && shown->height == frame->reconstruction.height &&
                  shown->slope_x == frame->reconstruction.slope_x;
  }
  return run;
}

}  // namespace

TEST_CASE("a stream carrying every 2nd tick predicts with the tick step") {
  const StepRun right = run_every_second_tick(30);
  const StepRun wrong = run_every_second_tick(0);  // dt = 1 / 15 per tick: twice the real step
  CHECK(right.bitwise);
  CHECK(wrong.bitwise);  // closed loop stays exact, only costlier
  CHECK(right.delta_bytes < wrong.delta_bytes);
}
