// FrameSource: what a viewer front end renders - the networked stream (NetworkSource in
// viewer_run.cpp) or the synthetic sea (SyntheticSource). The loops in viewer_loops.hpp own the
// GL context, the frame loop, camera input, the HUD and the screenshot; a source owns the scene
// and brings its uploaded frame up to date each frame.
#pragma once

#include <string>

#include "client/render/hud_overlay.hpp"
#include "client/viewer/view_scene.hpp"

namespace ocean::viewer {

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // With the GL context current: sets up scene(). False with a reason.
  virtual bool init(std::string& error) = 0;
  // Begins producing frames (the network thread connects). Called once, after init.
  virtual void start() {}
  // Headless only, after start: false with a reason when no frame came in time.
  virtual bool wait_for_first_frame(std::string& /*error*/) { return true; }
  // The time frame number frame_index is rendered at, given the seconds since the loop began.
  virtual double frame_time_s(int frame_index, double elapsed_s) const = 0;
  // Brings the uploaded frame to time t_s. False with a reason (the loop then stops).
  virtual bool update(double t_s, std::string& error) = 0;
  virtual render::HudStats hud_stats(double fps) const = 0;
  // The follow camera moves to the next vessel (after the last: free flight again).
  virtual void cycle_follow() {}
  // After the last frame, or when the loop gives up; may be called more than once.
  virtual void stop() {}

  virtual ViewScene& scene() = 0;
};

}  // namespace ocean::viewer
