// Touch controls for the web viewer on phones: one finger drags the view (as the mouse does), two
// fingers move the eye - spread them to go forward, pinch to go back, drag both to slide sideways
// or forward over the water. A pure function of the touches down after each browser touch event,
// so it is tested without a browser.
#pragma once

#include <span>
#include <vector>

#include "client/render/camera.hpp"
#include "client/render/camera_controls.hpp"

namespace ocean::render {

struct TouchPoint {
  long id = 0;
  double x_px = 0.0, y_px = 0.0;
};

// What the fingers did since the previous event.
struct TouchMotion {
  double look_dx_px = 0.0, look_dy_px = 0.0;  // one finger: as a mouse drag
  double forward_m = 0.0, right_m = 0.0;      // two fingers: along the horizontal view direction
};

struct TouchSettings {
  double metres_per_pinch_px = 0.5;  // finger spread change
  double metres_per_pan_px = 0.25;   // two-finger drag
};

class TouchGesture {
 public:
  // touches: every touch down now. A finger lifted or added starts a new gesture (no jump).
  TouchMotion update(std::span<const TouchPoint> touches, const TouchSettings& settings = {});

 private:
  std::vector<TouchPoint> last_;
};

// Turns the camera as apply_fly_input does for a drag, and moves it over the water.
void apply_touch_motion(Camera& camera, const TouchMotion& motion, const FlySettings& settings = {});

}  // namespace ocean::render
