// servable_scene (issue 33): at every corner of the documented ranges, alone and combined, on every
// profile, a scene is either refused with a reason that names the field, the profile and the
// figures, or its frames are carried: simulated and encoded with no value clamped and no throw.
// On main, desktop's wind 100 m/s with amplitude 1e5 passed the checks and stopped the server at
// the first tick ("Encoder::add_truth: height ... beyond 2^20 steps").
#include <catch2/catch.hpp>

#include "encoder.hpp"
#include "frame_producer.hpp"
#include "profile.hpp"
#include "servable_scene.hpp"
#include "stream_wire.hpp"

#include <functional>
#include <string>
#include <vector>

using namespace ocean;
using namespace ocean::server;
namespace model = ocean::model;

namespace {

std::vector<const Profile*> every_profile() {
  std::vector<const Profile*> out;
  for (const Profile& p : all_profiles()) out.push_back(&p);
  return out;
}

// The server's default lattice, which every profile fits.
model::SceneParams base_scene() {
  model::SceneParams scene;
  scene.size_x = scene.size_z = 256;
  scene.patch_x_m = scene.patch_z_m = 256.0;
  return scene;
}

// Simulates `scene` for every profile at a few times and encodes each frame as the server would;
// the samples any encoder had to clamp (0 for a carried scene).
std::uint64_t clamped_when_served(const model::SceneParams& scene, const std::vector<const Profile*>& profiles) {
  FrameProducer producer(SceneSchedule(scene, {}), profiles);
  const model::SceneParams model = scene;
  std::vector<codec::Encoder> encoders;
  for (const Profile* p : profiles) {
    codec::StreamConfig config = codec::StreamConfig::from_profile(*p, scene.patch_x_m, scene.patch_z_m, scene.gravity_mps2,
                                                                 model::wire_depth(scene.depth_m));
    config.tick_rate_hz = 30;
    encoders.emplace_back(config);
    encoders.back().set_scene(0, 0, model);
  }
  std::uint64_t clamped = 0;
  for (const std::int64_t tick : {30, 3000, 108000}) {  // 1 s, 100 s, an hour
    const auto frames = producer.produce(tick, static_cast<double>(tick) / 30.0);
    for (std::size_t i = 0; i < profiles.size(); ++i) {
      const sim::Frame& f = frames->frames[i].frame;
      encoders[i].add_truth(static_cast<Tick>(tick), codec::TruthView{f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z,
                                                                      f.disp_xx, f.disp_zz, f.disp_xz});
      (void)encoders[i].encode_key(static_cast<Tick>(tick));
    }
  }
  for (const auto& e : encoders) clamped += e.saturated_samples();
  return clamped;
}

struct Corner {
  std::string name;
  std::function<void(model::SceneParams&)> set;
};

}  // namespace

TEST_CASE("every corner of the documented ranges is refused with its figures or carried without clamping",
          "[servable]") {
  const std::vector<Corner> fields = {
      {"wind 0", [](model::SceneParams& s) { s.wind_speed_mps = 0.0; }},
      {"wind 100", [](model::SceneParams& s) { s.wind_speed_mps = 100.0; }},
      {"amplitude 0", [](model::SceneParams& s) { s.amplitude = 0.0; }},
      {"amplitude 1e6", [](model::SceneParams& s) { s.amplitude = 1e6; }},
      {"choppiness 0", [](model::SceneParams& s) { s.choppiness = 0.0; }},
      {"choppiness 100", [](model::SceneParams& s) { s.choppiness = 100.0; }},
      {"phillips", [](model::SceneParams& s) { s.spectrum = model::SpectrumKind::phillips; }},
      {"jonswap", [](model::SceneParams& s) { s.spectrum = model::SpectrumKind::jonswap; }},
      {"dir -1e6", [](model::SceneParams& s) { s.wind_dir_deg = -1e6; }},
      {"dir 1e6", [](model::SceneParams& s) { s.wind_dir_deg = 1e6; }},
  };
  // Alone: each field at each end; combined: wind, amplitude, choppiness and spectrum at every
  // pair of ends (the direction changes no magnitude), 16 scenes.
  std::vector<std::pair<std::string, model::SceneParams>> scenes;
  for (const Corner& c : fields) {
    model::SceneParams s = base_scene();
    c.set(s);
    scenes.emplace_back(c.name, s);
  }
  for (int bits = 0; bits < 16; ++bits) {
    model::SceneParams s = base_scene();
    std::string name;
    for (int f = 0; f < 4; ++f) {
      const Corner& c = fields[2 * f + ((bits >> f) & 1)];
      c.set(s);
      name += (name.empty() ? "" : ", ") + c.name;
    }
    scenes.emplace_back(name, s);
  }
  int refused = 0, carried = 0;
  for (const auto& [name, scene] : scenes) {
    for (const Profile* profile : every_profile()) {
      const std::vector<const Profile*> offered{profile};
      const std::string error = servable_scene(scene, offered);
      INFO(name << " on " << profile->name << ": " << (error.empty() ? "servable" : error));
      if (!error.empty()) {
        ++refused;
        CHECK(error.find(std::string(profile->name)) != std::string::npos);
        CHECK(error.find("RMS") != std::string::npos);
        continue;
      }
      ++carried;
      std::uint64_t clamped = 0;
      CHECK_NOTHROW(clamped = clamped_when_served(scene, offered));
      CHECK(clamped == 0);
    }
  }
  std::printf("[servable] %zu corner scenes x %zu profiles: %d carried, %d refused with their figures\n", scenes.size(),
              every_profile().size(), carried, refused);
  CHECK(carried > 0);
  CHECK(refused > 0);
}

TEST_CASE("the scenes that stopped main's server are refused with their figures, the default is served", "[servable]") {
  const auto on = [](const char* profile) { return std::vector<const Profile*>{find_profile(std::string_view(profile))}; };
  model::SceneParams storm = base_scene();
  storm.wind_speed_mps = 100.0;
  storm.amplitude = 1e5;
  const std::string error = servable_scene(storm, on("desktop"));
  INFO(error);
  CHECK(error.find("heights") != std::string::npos);
  CHECK(error.find("'desktop'") != std::string::npos);
  CHECK(servable_scene(base_scene(), every_profile()).empty());
  model::SceneParams gale = base_scene();  // a real gale at choppiness 1.2: served on every profile
  gale.spectrum = model::SpectrumKind::jonswap;
  gale.wind_speed_mps = 20.0;
  gale.choppiness = 1.2;
  CHECK(servable_scene(gale, every_profile()).empty());
}
