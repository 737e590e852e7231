// FpsMeter: frames per second over half-second windows - steady to read on a HUD, quick to
// follow a change. Time is passed in (seconds), so both viewers' loops share one rule.
#pragma once

namespace ocean::viewer {

class FpsMeter {
 public:
  // Counts one rendered frame at time now_s; returns the rate of the last complete window.
  double tick(double now_s) {
    if (!started_) {
      window_start_s_ = now_s;
      started_ = true;
    }
    const double window_s = now_s - window_start_s_;
    if (window_s >= 0.5) {
      fps_ = frames_ / window_s;
      frames_ = 0;
      window_start_s_ = now_s;
    }
    ++frames_;
    return fps_;
  }

 private:
  bool started_ = false;
  double window_start_s_ = 0.0;
  double fps_ = 0.0;
  int frames_ = 0;
};

}  // namespace ocean::viewer
