// HullMotion: how each vessel rides the sea a viewer decoded. Its place and heading come from its
// track (the Welcome's, as the server steers it); its heave, pitch and roll from the waves under
// it - five points (bow, stern, port, starboard, amidships) of the frame the viewer shows at that
// moment (codec::SurfaceQuery), so hull and water share one timeline - averaged over the hull as
// a hull's buoyancy averages the waves shorter than itself, then eased with time constants that
// grow with the hull (a hull's inertia) and never lag a swell by more than a few percent of its
// height. The waves are the sea's lattices: the wake lattice holds the depression each hull's own
// pressure makes under it (as deep as its draft), which is the water the hull displaces, not a
// trough to sink into; the keel is checked against the whole surface, depression included.
// Pure: the tracks, the frame and the time are arguments.
#pragma once

#include "surface_query.hpp"
#include "vessel_track.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

namespace ocean::client {

struct HullState {
  std::uint32_t id = 0;
  model::Hull hull;
  double x_m = 0.0, z_m = 0.0;        // amidships on the waterline
  double dir_x = 1.0, dir_z = 0.0;    // unit heading, towards the bow
  double speed_mps = 0.0;
  double heave_m = 0.0;               // the waterline's height
  double pitch_rad = 0.0;             // bow up positive
  double roll_rad = 0.0;              // starboard down positive
  // The decoded sea (its waves, the wake left out) at the five points (bow, stern, port,
  // starboard, amidships), and how far the keel under each stands above the whole decoded
  // surface there at most (the wake's depression included: at most about its draft).
  std::array<double, 5> surface_m{};
  double keel_above_m = 0.0;
};

// A dropped object presses on the water as a round hull (length = beam, PROTOCOL.md 8, drop): its
// rings are the wake's, but it is no vessel to draw, pose or follow.
inline bool is_dropped_object(const model::Hull& hull) { return hull.length_m == hull.beam_m; }

class HullMotion {
 public:
  // Every vessel present at t_s (track time: the server's tick / tick rate; dropped objects left
  // out), posed on `fields`,
  // the frame shown at t_s. A vessel first seen, or a jump in time, takes the surface's pose at once.
  const std::vector<HullState>& update(std::span<const model::VesselTrack> tracks, const codec::SurfaceQuery& sea,
                                       const codec::SurfaceFields& fields, double t_s);
  const std::vector<HullState>& hulls() const { return hulls_; }

  // The sample points as fractions of (length, beam), hull-local (+x bow, +z starboard).
  static constexpr std::array<std::array<double, 2>, 5> kPoints{{{0.4, 0.0}, {-0.4, 0.0}, {0.0, -0.4}, {0.0, 0.4}, {0.0, 0.0}}};

 private:
  std::vector<HullState> hulls_;
  std::map<std::uint32_t, HullState> previous_;
  double last_t_s_ = 0.0;
};

}  // namespace ocean::client
