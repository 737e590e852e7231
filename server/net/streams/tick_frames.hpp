// TickFrames: what one tick hands from the simulation thread to the network side: the frame of
// every offered profile, band-limited to the profile's grid, all at the same simulation time.
#pragma once

#include "frame.hpp"
#include "profile.hpp"
#include "scene_params.hpp"

#include <cstdint>
#include <vector>

namespace ocean::server {

struct ProfileFrame {
  const Profile* profile = nullptr;
  sim::Frame frame;
};

struct TickFrames {
  std::int64_t tick = 0;
  double time_s = 0.0;
  std::vector<ProfileFrame> frames;  // in the order of ServerConfig::profiles
  model::SceneParams scene;            // the scene these frames show
  bool scene_changed = false;        // this tick is the first of a new scene (schedule or admin)
  // Scene and fleet requests (override_scene, set_vessels) the producer had taken when it made
  // these frames: the network side knows from it whether a change it applied is in them yet.
  std::uint64_t requests_taken = 0;
};

}  // namespace ocean::server
