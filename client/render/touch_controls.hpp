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

// A double tap (two quick taps of one finger in one place): the browser's gesture for what the V
// key does (the follow camera's next vessel). Fed the touches down after each event and its time.
class DoubleTap {
 public:
  bool update(std::span<const TouchPoint> touches, double now_s);

  static constexpr double kTapS = 0.3, kBetweenS = 0.45, kSlopPx = 24.0;

 private:
  bool pressed_ = false, moved_ = false;
  TouchPoint start_{};
  double start_s_ = 0.0;
  double last_tap_s_ = -1e9;
  TouchPoint last_tap_{};
};

// Turns the camera as apply_fly_input does for a drag, and moves it over the water.
void apply_touch_motion(Camera& camera, const TouchMotion& motion, const FlySettings& settings = {});

}  // namespace ocean::render
