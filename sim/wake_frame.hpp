// The wake as a stream's lattice sees it: the WakeField's waves below a grid's Nyquist, sampled
// grid x grid over the wake region, with the channels a frame request names (heights, slopes, and
// the choppy displacement, its derivatives and Jacobian with the sim's formulas), so a wake adds
// to every channel the sea has.
#pragma once

#include "frame.hpp"
#include "ocean.hpp"
#include "wake_field.hpp"

#include <map>
#include <memory>
#include <span>

namespace ocean::sim {

class WakeSampler {
 public:
  WakeSampler();
  ~WakeSampler();
  WakeSampler(WakeSampler&&) noexcept;
  WakeSampler& operator=(WakeSampler&&) noexcept;

  // `out` becomes the wake's frame on a grid x grid lattice (a power of two, at most the field's n),
  // choppy channels scaled by `choppiness`.
  void sample(const WakeField& wake, int grid, FrameRequest request, double choppiness, Frame& out);
  // The same of the sum of several fields over one region.
  void sample(std::span<const WakeField* const> wakes, int grid, FrameRequest request, double choppiness, Frame& out);

  struct Plan;  // one grid's transform and wavenumbers (wake_frame.cpp)

 private:
  Plan& plan(int grid);
  std::map<int, std::unique_ptr<Plan>> plans_;
};

}  // namespace ocean::sim
