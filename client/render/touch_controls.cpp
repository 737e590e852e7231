#include "client/render/touch_controls.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {

namespace {

bool same_fingers(std::span<const TouchPoint> a, std::span<const TouchPoint> b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].id != b[i].id) return false;
  return true;
}

double spread(const TouchPoint& a, const TouchPoint& b) { return std::hypot(a.x_px - b.x_px, a.y_px - b.y_px); }

}  // namespace

TouchMotion TouchGesture::update(std::span<const TouchPoint> touches, const TouchSettings& s) {
  TouchMotion motion;
  if (same_fingers(touches, last_) && !touches.empty()) {
    if (touches.size() == 1) {
      motion.look_dx_px = touches[0].x_px - last_[0].x_px;
      motion.look_dy_px = touches[0].y_px - last_[0].y_px;
    } else {
      motion.forward_m = (spread(touches[0], touches[1]) - spread(last_[0], last_[1])) * s.metres_per_pinch_px;
      // Both fingers drag the water: moving them right slides the eye left, down brings it forward.
      const double mid_dx = (touches[0].x_px + touches[1].x_px - last_[0].x_px - last_[1].x_px) / 2.0;
      const double mid_dy = (touches[0].y_px + touches[1].y_px - last_[0].y_px - last_[1].y_px) / 2.0;
      motion.right_m = -mid_dx * s.metres_per_pan_px;
      motion.forward_m += mid_dy * s.metres_per_pan_px;
    }
  }
  last_.assign(touches.begin(), touches.end());
  return motion;
}

void apply_touch_motion(Camera& camera, const TouchMotion& motion, const FlySettings& settings) {
  FlyInput look;
  look.look_dx_px = motion.look_dx_px;
  look.look_dy_px = motion.look_dy_px;
  apply_fly_input(camera, look, 0.0, settings);
  glm::dvec3 ahead(camera.forward());
  ahead.y = 0.0;
  if (glm::length(ahead) < 1e-6) ahead = {0.0, 0.0, -1.0};  // looking straight down
  camera.position += glm::normalize(ahead) * motion.forward_m + glm::dvec3(camera.right()) * motion.right_m;
}

bool DoubleTap::update(std::span<const TouchPoint> touches, double now_s) {
  const auto far = [](const TouchPoint& a, const TouchPoint& b) {
    return std::hypot(a.x_px - b.x_px, a.y_px - b.y_px) > kSlopPx;
  };
  if (touches.size() > 1) {  // a pinch or a pan: no tap, and no pair with the one before
    pressed_ = false;
    last_tap_s_ = -1e9;
    return false;
  }
  if (touches.size() == 1) {
    if (!pressed_) {
      pressed_ = true;
      moved_ = false;
      start_ = touches[0];
      start_s_ = now_s;
    } else if (far(touches[0], start_)) {
      moved_ = true;  // a drag turns the view
    }
    return false;
  }
  if (!pressed_) return false;
  pressed_ = false;
  if (moved_ || now_s - start_s_ > kTapS) return false;
  const bool second = now_s - last_tap_s_ <= kBetweenS && !far(start_, last_tap_);
  last_tap_s_ = second ? -1e9 : now_s;
  last_tap_ = start_;
  return second;
}

}  // namespace ocean::render
