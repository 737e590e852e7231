// FoamMemory: whitecaps that fade instead of blinking. A choppy stream's Jacobian says where the
// surface folds now; foam lingers after the fold has passed. Each sample remembers the lowest
// Jacobian it has seen and recovers toward the current one at a fixed rate, so a crest's foam
// stays about (foam band / rate) seconds after the fold is gone and never appears before it.
#pragma once

#include <span>
#include <vector>

namespace ocean::render {

class FoamMemory {
 public:
  // Jacobian units per second; the renderer's foam band is 0.2 wide, so 0.2 fades full foam in
  // about a second.
  explicit FoamMemory(float recovery_per_s = 0.2f) : recovery_per_s_(recovery_per_s) {}

  // The Jacobian to shade with: min(J, remembered + rate * dt) per sample. A change of sample
  // count (a new grid) starts over; dt is clamped to [0, 1] s so a stall does not jump.
  const std::vector<float>& update(std::span<const float> jacobian, double dt_s);
  void clear() { memory_.clear(); }

 private:
  float recovery_per_s_;
  std::vector<float> memory_;
};

}  // namespace ocean::render
