// StreamConfig: built from each profile, and validate() names the bad field and its range.
#include "encoder.hpp"
#include "stream_config.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace ocean::codec;

TEST_CASE("from_profile copies the profile and the scene") {
  for (const ocean::Profile& p : ocean::all_profiles()) {
    const StreamConfig c = StreamConfig::from_profile(p, 200.0, 300.0, 9.8, 0.0);
    CHECK(c.profile_id == p.id);
    CHECK(c.grid == p.grid);
    CHECK(c.rate_hz == p.rate_hz);
    CHECK(c.height_step_m == p.height_step_m);
    CHECK(c.slope_step == p.slope_step);
    CHECK(c.normals == p.normals);
    CHECK(c.choppy == p.choppy);
    CHECK(c.patch_x_m == 200.0);
    CHECK(c.patch_z_m == 300.0);
    CHECK(c.depth_m == 0.0);  // deep water
    CHECK(c.disp_step_m == p.disp_step_m);
    CHECK(validate(c).empty());  // codec version 3 streams every profile, choppy ones too
  }
}

TEST_CASE("validate names each bad field") {
  auto bad = [](auto edit, const char* field) {
    StreamConfig c;
    edit(c);
    const std::string msg = validate(c);
    INFO(msg);
    CHECK(msg.find(field) != std::string::npos);
    CHECK_THROWS_WITH(Encoder(c), Catch::Contains(field));
  };
  bad([](StreamConfig& c) { c.grid = 48; }, "grid");
  bad([](StreamConfig& c) { c.grid = 1024; }, "grid");
  bad([](StreamConfig& c) { c.patch_x_m = 0; }, "patch_x_m");
  bad([](StreamConfig& c) { c.patch_z_m = -1; }, "patch_z_m");
  bad([](StreamConfig& c) { c.gravity_mps2 = 0; }, "gravity_mps2");
  bad([](StreamConfig& c) { c.depth_m = -3; }, "depth_m");
  bad([](StreamConfig& c) { c.rate_hz = 0; }, "rate_hz");
  bad([](StreamConfig& c) { c.height_step_m = 0; }, "height_step_m");
  bad([](StreamConfig& c) { c.slope_step = 2; }, "slope_step");
  bad([](StreamConfig& c) { c.choppy = true, c.disp_step_m = 0; }, "disp_step_m");
  bad([](StreamConfig& c) { c.choppy = true, c.normals = false, c.slope_step = 0; }, "slope_step");
}

TEST_CASE("encoder options are checked") {
  EncoderOptions o;
  o.max_payload = 10;
  CHECK_THROWS_WITH(Encoder(StreamConfig{}, o), Catch::Contains("max_payload"));
}

TEST_CASE("tick_rate_hz sets the step a delta advances by, 0 means rate_hz") {
  StreamConfig c;
  c.rate_hz = 15;
  CHECK(c.dt_s() == 1.0 / 15);
  c.tick_rate_hz = 30;
  CHECK(c.dt_s() == 1.0 / 30);
  CHECK(validate(c).empty());
  c.tick_rate_hz = 10;  // below the stream's own rate
  CHECK(validate(c).find("tick_rate_hz") != std::string::npos);
  StreamConfig same_as_rate;
  same_as_rate.tick_rate_hz = same_as_rate.rate_hz;
  CHECK(same_as_rate == StreamConfig{});  // explicit equal rate is the default
}
