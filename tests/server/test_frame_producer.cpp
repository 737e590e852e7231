#include "frame_producer.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
namespace model = ocean::model;

namespace {

ocean::model::SceneParams small_scene() {
  ocean::model::SceneParams scene;
  scene.size_x = scene.size_z = 64;
  scene.patch_x_m = scene.patch_z_m = 64.0;
  return scene;
}

std::vector<const ocean::Profile*> profiles(std::initializer_list<const char*> names) {
  std::vector<const ocean::Profile*> out;
  for (const char* name : names) out.push_back(ocean::find_profile(std::string_view(name)));
  return out;
}

}  // namespace

TEST_CASE("every offered profile gets its own band-limited frame", "[frame_producer]") {
  FrameProducer producer(SceneSchedule(small_scene(), {}), profiles({"lite", "mobile"}));
  const auto frames = producer.produce(42, 1.4);
  CHECK(frames->tick == 42);
  CHECK(frames->time_s == 1.4);
  REQUIRE(frames->frames.size() == 2);
  CHECK(frames->frames[0].profile->name == "lite");
  CHECK(frames->frames[0].frame.n_x == 32);
  CHECK(frames->frames[0].frame.height.size() == 32u * 32u);
  CHECK(frames->frames[0].frame.slope_x.size() == 32u * 32u);  // lite streams normals
  CHECK(frames->frames[1].frame.n_x == 64);
  CHECK(frames->frames[1].frame.time_s == 1.4);
}

TEST_CASE("two producers with one config give identical frames for a tick", "[frame_producer]") {
  FrameProducer a(SceneSchedule(small_scene(), {}), profiles({"mobile"}));
  FrameProducer b(SceneSchedule(small_scene(), {}), profiles({"mobile"}));
  (void)b.produce(7, 7.0 / 30);  // b has history a lacks: it must not matter
  const auto fa = a.produce(1000, 1000.0 / 30);
  const auto fb = b.produce(1000, 1000.0 / 30);
  CHECK(fa->frames[0].frame.height == fb->frames[0].frame.height);
  CHECK(fa->frames[0].frame.slope_z == fb->frames[0].frame.slope_z);
  const auto later = a.produce(1001, 1001.0 / 30);
  CHECK(later->frames[0].frame.height != fb->frames[0].frame.height);
}

TEST_CASE("results held by the network side are never overwritten", "[frame_producer]") {
  FrameProducer producer(SceneSchedule(small_scene(), {}), profiles({"mobile"}));
  const auto held = producer.produce(1, 1.0 / 30);
  const std::vector<float> copy = held->frames[0].frame.height;
  for (int tick = 2; tick < 20; ++tick) (void)producer.produce(tick, tick / 30.0);
  CHECK(held->tick == 1);
  CHECK(held->frames[0].frame.height == copy);
}

TEST_CASE("released results are reused without reallocating", "[frame_producer]") {
  FrameProducer producer(SceneSchedule(small_scene(), {}), profiles({"mobile"}));
  auto first = producer.produce(1, 1.0 / 30);
  const TickFrames* address = first.get();
  const float* heights = first->frames[0].frame.height.data();
  first.reset();  // the network side is done with it
  const auto second = producer.produce(2, 2.0 / 30);
  CHECK(second.get() == address);
  CHECK(second->frames[0].frame.height.data() == heights);
  CHECK(second->tick == 2);
}

TEST_CASE("a scheduled scene takes over from its tick", "[frame_producer][schedule]") {
  ocean::model::SceneParams calm = small_scene();
  ocean::model::SceneParams windy = calm;
  windy.wind_speed_mps = 20.0;
  FrameProducer scheduled(SceneSchedule(calm, {{100, windy}}), profiles({"mobile"}));
  FrameProducer calm_only(SceneSchedule(calm, {}), profiles({"mobile"}));
  FrameProducer windy_only(SceneSchedule(windy, {}), profiles({"mobile"}));

  const double t99 = 99 / 30.0, t100 = 100 / 30.0;
  CHECK(scheduled.produce(99, t99)->frames[0].frame.height == calm_only.produce(99, t99)->frames[0].frame.height);
  CHECK_FALSE(scheduled.scene_changed());
  CHECK(scheduled.produce(100, t100)->frames[0].frame.height ==
        windy_only.produce(100, t100)->frames[0].frame.height);
  CHECK(scheduled.scene_changed());
  CHECK(scheduled.scene().wind_speed_mps == 20.0);
  (void)scheduled.produce(101, 101 / 30.0);
  CHECK_FALSE(scheduled.scene_changed());
}

TEST_CASE("desktop and desktop-choppy share one evaluation of their cascades, each frame as alone", "[frame_producer]") {
  ocean::model::SceneParams storm = small_scene();
  storm.spectrum = ocean::model::SpectrumKind::jonswap;
  storm.wind_speed_mps = 20.0;
  storm.choppiness = 1.2;
  FrameProducer both(SceneSchedule(storm, {}), profiles({"desktop", "mobile", "desktop-choppy"}));
  FrameProducer plain(SceneSchedule(storm, {}), profiles({"desktop"}));
  FrameProducer choppy(SceneSchedule(storm, {}), profiles({"desktop-choppy"}));
  for (std::int64_t tick : {30, 31, 95}) {
    const double t = static_cast<double>(tick) / 30.0;
    const auto shared = both.produce(tick, t);
    const auto alone = plain.produce(tick, t);
    const auto alone_choppy = choppy.produce(tick, t);
    const ocean::sim::Frame& d = shared->frames[0].frame;
    const ocean::sim::Frame& c = shared->frames[2].frame;
    const ocean::sim::Frame& d1 = alone->frames[0].frame;
    const ocean::sim::Frame& c1 = alone_choppy->frames[0].frame;
    INFO("tick " << tick);
    REQUIRE(d.height.size() == 256u * 256u + 128u * 128u);
    CHECK(d.height == d1.height);
    CHECK(d.slope_x == d1.slope_x);
    CHECK(d.slope_z == d1.slope_z);
    CHECK(d.disp_x.empty());  // desktop streams no choppy channels
    CHECK(d.jacobian.empty());
    CHECK(d.time_s == d1.time_s);
    CHECK(c.height == c1.height);
    CHECK(c.slope_z == c1.slope_z);
    CHECK(c.disp_x == c1.disp_x);
    CHECK(c.disp_xz == c1.disp_xz);
    CHECK(c.jacobian == c1.jacobian);
    CHECK_FALSE(c.jacobian.empty());
    CHECK(shared->frames[1].frame.height.size() == 64u * 64u);
  }
}

// Scenes known ahead (the schedule's next entry, an admin change a lead before its tick) are built
// on the producer's BuildQueue while it steps on; a producer that meets the same scenes with no
// warning builds them at the tick. Their frames must be the same bits.
TEST_CASE("a scene built ahead of its tick gives the bits of one built at it", "[frame_producer][schedule]") {
  ocean::model::SceneParams calm = small_scene();
  ocean::model::SceneParams gale = calm, storm = calm;
  gale.wind_speed_mps = 20.0;
  storm.spectrum = ocean::model::SpectrumKind::jonswap;
  storm.wind_speed_mps = 15.0;
  storm.choppiness = 1.2;
  const auto names = {"mobile", "desktop-choppy", "lite"};
  FrameProducer stepping(SceneSchedule(calm, {{40, gale}}), profiles(names));
  for (std::int64_t tick = 0; tick < 70; ++tick) {
    if (tick == 30) stepping.override_scene(storm, 60);  // an admin change, a second ahead
    const auto frames = stepping.produce(tick, static_cast<double>(tick) / 30.0);
    CHECK(stepping.scene_changed() == (tick == 40 || tick == 60));
    if (tick != 40 && tick != 60 && tick != 69) continue;
    // The scene in force, as a producer started there meets it: built when asked for.
    FrameProducer fresh(SceneSchedule(tick < 60 ? gale : storm, {}), profiles(names));
    const auto expected = fresh.produce(tick, static_cast<double>(tick) / 30.0);
    INFO("tick " << tick);
    for (std::size_t i = 0; i < frames->frames.size(); ++i) {
      CHECK(frames->frames[i].frame.height == expected->frames[i].frame.height);
      CHECK(frames->frames[i].frame.slope_x == expected->frames[i].frame.slope_x);
      CHECK(frames->frames[i].frame.jacobian == expected->frames[i].frame.jacobian);
    }
  }
  CHECK(stepping.scene().choppiness == 1.2);
}
