#include "hull_motion.hpp"

#include <cmath>

namespace ocean::client {
namespace {

// Seconds: a hull of length L eases heave, pitch and roll with these times (a 25 m hull: 0.15,
// 0.25, 0.4 s). A swell of period T is then followed with a lag of 2 pi tau / T of its amplitude
// (heave: 12 % at 8 s, 6 % of the wave's height).
double heave_tau(const model::Hull& h) { return 0.03 * std::sqrt(h.length_m); }
double pitch_tau(const model::Hull& h) { return 0.05 * std::sqrt(h.length_m); }
double roll_tau(const model::Hull& h) { return 0.08 * std::sqrt(h.length_m); }

double ease(double from, double to, double dt, double tau) { return to + (from - to) * std::exp(-dt / tau); }

}  // namespace

const std::vector<HullState>& HullMotion::update(std::span<const model::VesselTrack> tracks, const codec::SurfaceQuery& sea,
                                                 const codec::SurfaceFields& fields, double t_s) {
  const double dt = t_s - last_t_s_;
  const bool continuous = dt > 0.0 && dt < 1.0;  // else every hull takes the surface's pose at once
  last_t_s_ = t_s;
  hulls_.clear();
  for (const model::VesselTrack& track : tracks) {
    if (!model::present_at(track.presence, t_s) || is_dropped_object(track.hull)) continue;
    const model::HullPose pose = model::pose_at(track, t_s);
    const model::HullPose later = model::pose_at(track, t_s + 0.5), earlier = model::pose_at(track, t_s - 0.5);
    HullState s;
    s.id = track.id;
    s.hull = track.hull;
    s.x_m = pose.x_m;
    s.z_m = pose.z_m;
    s.dir_x = pose.dir_x;
    s.dir_z = pose.dir_z;
    s.speed_mps = std::hypot(later.x_m - earlier.x_m, later.z_m - earlier.z_m);
    // Starboard: the heading turned a right angle (a heading along +x has starboard along +z).
    const double side_x = -pose.dir_z, side_z = pose.dir_x;
    std::array<double, 5> whole{}, along{}, across{};
    for (std::size_t i = 0; i < kPoints.size(); ++i) {
      along[i] = kPoints[i][0] * track.hull.length_m, across[i] = kPoints[i][1] * track.hull.beam_m;
      const double x = s.x_m + along[i] * pose.dir_x + across[i] * side_x;
      const double z = s.z_m + along[i] * pose.dir_z + across[i] * side_z;
      s.surface_m[i] = sea.height_at(fields, x, z, codec::SurfaceQuery::Lattices::sea);
      whole[i] = sea.height_at(fields, x, z);
    }
    const auto& h = s.surface_m;
    const double heave = (h[0] + h[1] + h[2] + h[3] + 2.0 * h[4]) / 6.0;
    const double pitch = std::atan2(h[0] - h[1], 0.8 * track.hull.length_m);
    const double roll = std::atan2(h[2] - h[3], 0.8 * track.hull.beam_m);
    const auto before = previous_.find(track.id);
    if (continuous && before != previous_.end()) {
      s.heave_m = ease(before->second.heave_m, heave, dt, heave_tau(track.hull));
      s.pitch_rad = ease(before->second.pitch_rad, pitch, dt, pitch_tau(track.hull));
      s.roll_rad = ease(before->second.roll_rad, roll, dt, roll_tau(track.hull));
    } else {
      s.heave_m = heave;
      s.pitch_rad = pitch;
      s.roll_rad = roll;
    }
    // The keel under each point: the waterline's plane through the pose, less the draft.
    s.keel_above_m = -1e9;
    for (std::size_t i = 0; i < kPoints.size(); ++i) {
      const double waterline = s.heave_m + along[i] * std::tan(s.pitch_rad) - across[i] * std::tan(s.roll_rad);
      s.keel_above_m = std::max(s.keel_above_m, waterline - track.hull.draft_m - whole[i]);
    }
    hulls_.push_back(s);
  }
  previous_.clear();
  for (const HullState& s : hulls_) previous_[s.id] = s;
  return hulls_;
}

}  // namespace ocean::client
