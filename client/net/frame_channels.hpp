// FrameChannels: what a renderer draws of a moment - the channels a viewer keeps of a frame,
// blended between two frames. Plain vectors, so the renderer can take it without the codec.
#pragma once

#include "common/channels.hpp"

#include <array>
#include <utility>
#include <vector>

namespace ocean::client {

struct FrameChannels {
  std::vector<float> height, slope_x, slope_z;
  std::vector<float> disp_x, disp_z, jacobian;  // empty unless the stream is choppy
};

// The channels (common/channels.hpp) a viewer keeps, and where: the displacement's derivatives
// only make the Jacobian, which the decoder computes and the viewer keeps beside them.
inline constexpr std::pair<ChannelId, std::vector<float> FrameChannels::*> kViewerChannels[] = {
    {ChannelId::height, &FrameChannels::height}, {ChannelId::slope_x, &FrameChannels::slope_x},
    {ChannelId::slope_z, &FrameChannels::slope_z}, {ChannelId::disp_x, &FrameChannels::disp_x},
    {ChannelId::disp_z, &FrameChannels::disp_z}};

}  // namespace ocean::client
