#include "servable_scene.hpp"

#include "cascade_scene.hpp"
#include "field_extent.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace ocean::server {
namespace {

std::string figure(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// "" when a field of this RMS fits 2^20 steps with the headroom.
std::string fits(const char* field, double rms, double step, const char* unit, const Profile& profile,
                 const std::string& lattice) {
  const double range = std::ldexp(step, 20);
  if (kHeadroom * rms < range) return "";
  return "the scene's " + std::string(field) + " would be about " + figure(rms) + unit + " RMS" + lattice +
         ", but profile '" + std::string(profile.name) + "' carries at most +-" + figure(range) + unit + " (2^20 steps of " +
         figure(step) + unit + ", and peaks reach " + figure(kHeadroom) +
         " RMS): lower the amplitude, the wind speed or the choppiness";
}

// Each lattice's extent once: profiles share lattices (mobile and mobile-choppy one grid, the
// desktops their cascades), and each extent is a sum over every mode of the lattice.
class Extents {
 public:
  const sim::FieldExtent& of(const model::SceneParams& lattice) {
    for (const auto& [params, extent] : known_)
      if (params == lattice) return extent;
    return known_.emplace_back(lattice, sim::expected_extent(lattice)).second;
  }

 private:
  std::vector<std::pair<model::SceneParams, sim::FieldExtent>> known_;
};

std::string lattice_fits(const sim::FieldExtent& e, const Profile& profile, const std::string& where) {
  std::string error = fits("heights", e.height_m, profile.height_step_m, " m", profile, where);
  if (error.empty() && profile.normals) error = fits("slopes", e.slope, profile.slope_step, "", profile, where);
  if (error.empty() && profile.choppy)
    error = fits("choppy displacement", e.displacement_m, profile.disp_step_m, " m", profile, where);
  if (error.empty() && profile.choppy)
    error = fits("choppy displacement's derivatives", e.displacement_slope, profile.slope_step, "", profile, where);
  return error;
}

}  // namespace

std::string servable_scene(const model::SceneParams& scene, std::span<const Profile* const> profiles) {
  if (std::string error = model::validate(scene); !error.empty()) return error;
  Extents extents;
  for (const Profile* profile : profiles) {
    if (profile->cascades.empty()) {
      model::SceneParams lattice = scene;  // the profile's grid of the scene's own lattice
      lattice.size_x = std::min(scene.size_x, static_cast<int>(profile->grid));
      lattice.size_z = std::min(scene.size_z, static_cast<int>(profile->grid));
      if (std::string error = lattice_fits(extents.of(lattice), *profile, ""); !error.empty()) return error;
      continue;
    }
    for (std::size_t c = 0; c < profile->cascades.size(); ++c) {
      model::SceneParams lattice;
      try {
        lattice = model::cascade_scene(scene, profile->cascades[c], static_cast<int>(c));
      } catch (const model::ParamError& e) {
        return "profile '" + std::string(profile->name) + "' cannot realize its " + e.what();
      }
      if (std::string error = lattice_fits(extents.of(lattice), *profile, " on cascade " + std::to_string(c));
          !error.empty())
        return error;
    }
  }
  return "";
}

}  // namespace ocean::server
