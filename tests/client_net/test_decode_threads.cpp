// The threads a client lends its decoder (ocean-viewer: WorkerPool over its spare cores, through
// ClientSessionConfig::decode_parallel): the pool runs every job of a call exactly once and really
// side by side, and synthesis and the output conversion spread over it give the bits they give on
// one thread. Here because
// these tests also run under ThreadSanitizer.
#include "decoder.hpp"
#include "encoder.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "cascade_set.hpp"
#include "ocean.hpp"
#include "profile.hpp"
#include "stream_config.hpp"
#include "worker_pool.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <map>
#include <condition_variable>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

using namespace ocean;
namespace model = ocean::model;

TEST_CASE("WorkerPool runs every job of every call exactly once") {
  for (int helpers : {0, 1, 3}) {
    WorkerPool pool(helpers);
    CHECK(pool.helpers() == helpers);
    for (int call = 0; call < 200; ++call) {
      const int count = call % 9;  // 0 and 1 included: they run on the caller
      std::vector<std::atomic<int>> runs(count);
      pool.run(count, [&](int i) { runs[i].fetch_add(1); });
      for (int i = 0; i < count; ++i) REQUIRE(runs[i].load() == 1);
    }
  }
}

TEST_CASE("WorkerPool runs a call's jobs side by side") {
  WorkerPool pool(1);
  // Each of the two jobs waits for the other to start: only two threads at once can finish.
  std::mutex m;
  std::condition_variable cv;
  int started = 0;
  bool both = true;
  pool.run(2, [&](int) {
    std::unique_lock lock(m);
    ++started;
    cv.notify_all();
    if (!cv.wait_for(lock, std::chrono::seconds(20), [&] { return started == 2; })) both = false;
  });
  CHECK(both);
}

TEST_CASE("synthesis spread over threads gives the bits of one thread") {
  for (const char* name : {"mobile-choppy", "desktop-choppy", "desktop", "lite"}) {
    const Profile* p = find_profile(name);
    REQUIRE(p);
    const codec::StreamConfig config = codec::StreamConfig::from_profile(*p, 256.0, 256.0, 9.81, 0.0);
    codec::ModalModel alone(config), spread(config);
    WorkerPool pool(2);
    spread.set_parallel([&pool](int count, const std::function<void(int)>& job) { pool.run(count, job); });
    codec::ModalState state = alone.zero_state();
    std::mt19937_64 rng(11);
    for (auto* v : {&state.cur.re, &state.cur.im})
      for (std::int64_t& x : *v) x = static_cast<std::int64_t>(rng() >> 24) - (std::int64_t{1} << 39);
    for (double choppiness : {1.2, 0.0, 0.5}) {
      codec::SampleFields a, b;
      alone.synthesize(state.cur, choppiness, a);
      spread.synthesize(state.cur, choppiness, b);
      INFO(name << " choppiness " << choppiness);
      for (int ch = 0; ch < kChannelCount; ++ch) CHECK(a[ch] == b[ch]);
      CHECK(!a[ChannelId::height].empty());
      // The output floats too: four parts of the samples side by side.
      codec::ReconstructedFrame fa, fb;
      codec::to_float(a, config, fa);
      codec::to_float(a, config, fb, [&pool](int count, const std::function<void(int)>& job) { pool.run(count, job); });
      CHECK(fa.height == fb.height);
      CHECK(fa.slope_z == fb.slope_z);
      CHECK(fa.disp_xz == fb.disp_xz);
      CHECK(fa.jacobian == fb.jacobian);
      CHECK(fa.jacobian.size() == (p->choppy ? a[ChannelId::height].size() : 0));
    }
  }
}

TEST_CASE("a decoder lent threads decodes a storm to the bits of one without") {
  codec::StreamConfig config = codec::StreamConfig::from_profile(*find_profile("desktop-choppy"), 256.0, 256.0, 9.81, 0.0);
  // The smallest grid a decoder spreads, to keep this quick under sanitizers, as desktop-choppy's
  // tile and coarse cascade.
  config.grid = 128;
  config.cascades = {{1, 128, {8, 0}}, {8, 64, {0, 64}}};
  model::SceneParams scene;
  scene.spectrum = model::SpectrumKind::jonswap;
  scene.wind_speed_mps = 20.0;
  scene.choppiness = 1.2;
  WorkerPool pool(2);
  codec::DecoderOptions lent;
  lent.parallel = [&pool](int count, const std::function<void(int)>& job) { pool.run(count, job); };
  codec::Encoder encoder(config);
  codec::Decoder alone(config), spread(config, lent);
  encoder.set_scene(0, 1, scene);
  alone.add_scene(0, 1, scene);
  spread.add_scene(0, 1, scene);
  sim::CascadeSet cascades(scene, config.cascades);
  sim::Frame frame;
  std::map<Tick, codec::StateId> ids;
  const Tick first = 1'000'000'000;
  for (Tick tick = first; tick < first + 8; ++tick) {
    cascades.evaluate(codec::tick_time_s(static_cast<std::int64_t>(tick), config.rate_hz), frame, sim::FrameRequest{true, true});
    encoder.add_truth(tick, codec::TruthView{frame.height, frame.slope_x, frame.slope_z, frame.disp_x, frame.disp_z,
                                             frame.disp_xx, frame.disp_zz, frame.disp_xz});
    // Lags of 1 and 3 ticks: the recurrence's parts run one step and several.
    const auto encoded = tick == first ? encoder.encode_key(tick)
                                       : encoder.encode_delta(tick, ids.at(tick - (tick >= first + 3 ? 3 : 1)));
    ids[tick] = encoded->id;
    for (const codec::Chunk& chunk : encoded->chunks) {
      REQUIRE(alone.accept(chunk) == codec::ChunkError::ok);
      REQUIRE(spread.accept(chunk) == codec::ChunkError::ok);
    }
    const codec::ReconstructedFrame* a = alone.latest();
    const codec::ReconstructedFrame* b = spread.latest();
    REQUIRE(a);
    REQUIRE(b);
    INFO("tick " << tick - first);
    CHECK(b->height == a->height);
    CHECK(b->slope_x == a->slope_x);
    CHECK(b->disp_z == a->disp_z);
    CHECK(b->jacobian == a->jacobian);
    CHECK(b->height == encoded->reconstruction.height);
    CHECK(*spread.state(tick) == *alone.state(tick));
  }
}
