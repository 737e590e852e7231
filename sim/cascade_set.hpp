// CascadeSet: the Oceans of a stream's cascades (cascade_scene.hpp), evaluated together into one
// frame whose fields hold every cascade's samples one after the other - a cascaded stream's truth
// as the server encodes it, a load test checks it and a benchmark measures it.
#pragma once

#include "cascade_scene.hpp"
#include "cascade_frame.hpp"
#include "ocean.hpp"

#include <span>
#include <vector>

namespace ocean::sim {

class CascadeSet {
 public:
  // Throws ParamError when a cascade or the scene it makes is unusable.
  CascadeSet(const SceneParams& scene, std::span<const Cascade> cascades);

  // Every cascade's frame at time t, appended in order (append_cascade_frame).
  void evaluate(double t, Frame& out, FrameRequest request = {});

  std::size_t size() const { return oceans_.size(); }

 private:
  std::vector<Ocean> oceans_;
  Frame part_;
};

}  // namespace ocean::sim
