// Fly-camera controls: what WASD and a mouse drag do to a Camera, as a pure function of the
// input state and the elapsed time, so the window layer only gathers input.
#pragma once

#include "client/render/camera.hpp"

namespace ocean::render {

struct FlyInput {
  bool forward = false, back = false, left = false, right = false;
  bool up = false, down = false;    // vertical (E/Space up, C down)
  bool fast = false;                // shift: ten times faster
  double look_dx_px = 0.0;          // mouse movement while the button is held, pixels
  double look_dy_px = 0.0;
};

struct FlySettings {
  float speed_m_per_s = 20.0f;
  float look_rad_per_px = 0.003f;
  float min_eye_height_m = 1.0f;    // stay above the mean sea surface
};

void apply_fly_input(Camera& camera, const FlyInput& input, double dt_s, const FlySettings& settings = {});

}  // namespace ocean::render
