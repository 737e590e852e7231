// VesselView: the vessels of a viewer's scene, the same in the native and the browser viewer:
// each rendered frame, every vessel present is posed on the frame shown (client::HullMotion), as
// a hull to draw and a foam trail for the water; a follow camera rides behind and above one of
// them; the HUD's line names those in view. Pure over its arguments (no GL, no network).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "client/render/camera.hpp"
#include "client/render/hull_renderer.hpp"
#include "client/render/renderer.hpp"
#include "hull_motion.hpp"

namespace ocean::viewer {

class VesselView {
 public:
  // Poses the vessels at t_s (track time) on `fields`; fills the hulls to draw and the renderer's
  // trails, and moves the camera when it follows one.
  const std::vector<client::HullState>& update(std::span<const model::VesselTrack> tracks, const codec::SurfaceQuery& sea,
                                               const codec::SurfaceFields& fields, double t_s,
                                               std::vector<render::HullInstance>& hulls, render::Renderer& renderer,
                                               render::Camera& camera);
  const std::vector<client::HullState>& hulls() const { return motion_.hulls(); }

  // -1: free flight. cycle_follow() moves to the next vessel present, after the last back to -1.
  void set_follow(std::int64_t id) { follow_id_ = id, eased_ = false; }
  void cycle_follow();
  std::int64_t follow_id() const { return follow_id_; }
  // "vessel 3 7.0 m/s (following), ..." of the hulls drawn (indices into update()'s hulls).
  std::string in_view(const std::vector<std::size_t>& drawn) const;

 private:
  void follow(const client::HullState& hull, double dt_s, render::Camera& camera);

  client::HullMotion motion_;
  std::vector<render::FoamTrail> trails_;  // this frame's, kept for its capacity
  std::int64_t follow_id_ = -1;
  bool eased_ = false;  // the follow camera has a previous pose to ease from
  double last_t_s_ = 0.0;
};

// Hull-local +x (bow), +y (up), +z (starboard) turned by the pose's heading, pitch and roll.
render::HullInstance hull_instance(const client::HullState& hull);

}  // namespace ocean::viewer
