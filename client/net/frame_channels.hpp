// FrameChannels: what a renderer draws of a moment - every channel the stream carries, blended
// between two frames. Plain vectors, so the renderer can take it without the codec.
#pragma once

#include <vector>

namespace ocean::client {

struct FrameChannels {
  std::vector<float> height, slope_x, slope_z;
  std::vector<float> disp_x, disp_z, jacobian;  // empty unless the stream is choppy
};

}  // namespace ocean::client
