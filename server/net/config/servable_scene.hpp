// servable_scene: the one check every scene passes before the server computes it - from flags,
// the config file, its schedule or an admin ParamChange (and, later, a fleet's timeline). A scene
// is servable when the sim accepts it (model::validate, the documented ranges) and every offered
// profile's stream can carry its fields: each lattice's expected RMS (sim::expected_extent) times
// kHeadroom within the codec's 2^20 quantization steps of that profile. Inside the documented
// ranges some combinations are not (wind 100 m/s with amplitude 1e5 makes kilometre waves); they
// are refused with their figures instead of stopping the server at the first tick.
#pragma once

#include "profile.hpp"
#include "scene_params.hpp"

#include <span>
#include <string>

namespace ocean::server {

// A field's peak over a frame, and over the hours a scene lasts, stays far below this many RMS:
// a Gaussian sea's tallest of 10^5 samples is about 4.5 RMS, and a lattice whose variance sits in
// a few modes may draw twice its expected RMS.
inline constexpr double kHeadroom = 16.0;

// "" when servable, else the first reason, naming the field, the profile and the figures.
std::string servable_scene(const model::SceneParams& scene, std::span<const Profile* const> profiles);

}  // namespace ocean::server
