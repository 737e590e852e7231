#include "client/viewer/vessel_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ocean::viewer {
namespace {

// A hull's trail from its pose: churned white at the stern for a fast hull, none below 1 m/s, as
// long as ten seconds of its run (at most 150 m), a little narrower than the hull at first.
render::FoamTrail foam_trail(const client::HullState& h) {
  render::FoamTrail t;
  t.stern_x_m = h.x_m - 0.5 * h.hull.length_m * h.dir_x;
  t.stern_z_m = h.z_m - 0.5 * h.hull.length_m * h.dir_z;
  t.dir_x = static_cast<float>(h.dir_x);
  t.dir_z = static_cast<float>(h.dir_z);
  t.length_m = static_cast<float>(std::min(10.0 * h.speed_mps, 150.0));
  t.half_width_m = static_cast<float>(0.4 * h.hull.beam_m);
  t.spread = 0.06f;
  t.strength = static_cast<float>(std::clamp((h.speed_mps - 1.0) / 6.0, 0.0, 1.0));
  return t;
}

}  // namespace

render::HullInstance hull_instance(const client::HullState& h) {
  const glm::vec3 bow(static_cast<float>(h.dir_x), 0.0f, static_cast<float>(h.dir_z));
  const glm::vec3 starboard(-bow.z, 0.0f, bow.x), up(0.0f, 1.0f, 0.0f);
  const float cp = std::cos(static_cast<float>(h.pitch_rad)), sp = std::sin(static_cast<float>(h.pitch_rad));
  const float cr = std::cos(static_cast<float>(h.roll_rad)), sr = std::sin(static_cast<float>(h.roll_rad));
  const glm::vec3 fwd = cp * bow + sp * up;             // the bow up by the pitch
  const glm::vec3 lifted = -sp * bow + cp * up;
  const glm::vec3 side = cr * starboard - sr * lifted;  // starboard down by the roll
  const glm::vec3 top = sr * starboard + cr * lifted;
  render::HullInstance hull;
  hull.position = {h.x_m, h.heave_m, h.z_m};
  hull.rotation = glm::mat3(fwd, top, side);
  hull.length_m = static_cast<float>(h.hull.length_m);
  hull.beam_m = static_cast<float>(h.hull.beam_m);
  hull.draft_m = static_cast<float>(h.hull.draft_m);
  return hull;
}

const std::vector<client::HullState>& VesselView::update(std::span<const model::VesselTrack> tracks,
                                                         const codec::SurfaceQuery& sea, const codec::SurfaceFields& fields,
                                                         double t_s, std::vector<render::HullInstance>& hulls,
                                                         render::Renderer& renderer, render::Camera& camera) {
  const std::vector<client::HullState>& posed = motion_.update(tracks, sea, fields, t_s);
  hulls.clear();
  trails_.clear();
  for (const client::HullState& h : posed) {
    hulls.push_back(hull_instance(h));
    trails_.push_back(foam_trail(h));
  }
  renderer.set_trails(trails_);
  const double dt = t_s - last_t_s_;
  last_t_s_ = t_s;
  const auto followed = std::find_if(posed.begin(), posed.end(), [&](const client::HullState& h) { return h.id == follow_id_; });
  if (followed != posed.end()) follow(*followed, dt, camera);
  else eased_ = false;
  return posed;
}

// Behind and above the hull, looking past it along its heading; eased (about a second) so a turn
// at a waypoint swings the view round instead of snapping it.
void VesselView::follow(const client::HullState& h, double dt_s, render::Camera& camera) {
  const double back = 2.2 * h.hull.length_m + 15.0, up = 0.5 * h.hull.length_m + 6.0;
  const glm::dvec3 target(h.x_m - back * h.dir_x, h.heave_m + up, h.z_m - back * h.dir_z);
  const float yaw = static_cast<float>(std::atan2(-h.dir_x, -h.dir_z));
  if (!eased_ || dt_s <= 0.0 || dt_s > 1.0) {
    camera.position = target;
    camera.yaw_rad = yaw;
  } else {
    const double k = 1.0 - std::exp(-dt_s / 0.8);
    camera.position += (target - camera.position) * k;
    const float turn = std::remainder(yaw - camera.yaw_rad, 2.0f * 3.14159265f);  // the short way round
    camera.yaw_rad += static_cast<float>(k) * turn;
  }
  camera.pitch_rad = -0.8f * static_cast<float>(std::atan2(up, back));
  eased_ = true;
}

void VesselView::cycle_follow() {
  const std::vector<client::HullState>& hulls = motion_.hulls();
  const auto at = std::find_if(hulls.begin(), hulls.end(), [&](const client::HullState& h) { return h.id == follow_id_; });
  follow_id_ = at == hulls.end() ? (hulls.empty() ? -1 : hulls.front().id) : (at + 1 == hulls.end() ? -1 : (at + 1)->id);
  eased_ = false;
}

std::string VesselView::in_view(const std::vector<std::size_t>& drawn) const {
  // One line each, the followed one first; a HUD line of its own for each of the first four.
  constexpr std::size_t kListed = 4;
  const std::vector<client::HullState>& hulls = motion_.hulls();
  std::vector<std::size_t> shown;
  for (const std::size_t i : drawn)
    if (i < hulls.size()) shown.push_back(i);
  std::stable_partition(shown.begin(), shown.end(), [&](std::size_t i) { return hulls[i].id == follow_id_; });
  std::string text;
  char line[64];
  for (std::size_t n = 0; n < shown.size() && n < kListed; ++n) {
    const client::HullState& h = hulls[shown[n]];
    std::snprintf(line, sizeof line, "%svessel %u %.1f m/s%s", n ? "\n" : "", h.id, h.speed_mps,
                  h.id == follow_id_ ? " (following)" : "");
    text += line;
  }
  if (shown.size() > kListed) text += "\n+" + std::to_string(shown.size() - kListed) + " more vessels in view";
  return text;
}

}  // namespace ocean::viewer
