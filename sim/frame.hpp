// Frame: one evaluated tick of the ocean, row-major with z as rows and x as columns.
#pragma once

#include "common/channels.hpp"

#include <array>
#include <vector>

namespace ocean::sim {

struct Frame {
  int n_x = 0;
  int n_z = 0;
  double patch_x_m = 0.0;
  double patch_z_m = 0.0;
  double time_s = 0.0;
  std::vector<float> height;    // metres, index z * n_x + x
  std::vector<float> slope_x;   // dh/dx, empty unless requested
  std::vector<float> slope_z;   // dh/dz, empty unless requested
  std::vector<float> disp_x;    // choppy displacement in metres (lambda applied), empty unless choppy
  std::vector<float> disp_z;
  // Choppy: the displacement's derivatives dDx/dx, dDz/dz, dDx/dz (lambda applied), the inputs of
  // the Jacobian (1 + xx)(1 + zz) - xz^2 of the displaced grid; < ~0.3 means folding (foam).
  std::vector<float> disp_xx, disp_zz, disp_xz;
  std::vector<float> jacobian;
};

// Frame's field of each channel (common/channels.hpp), in the table's order.
inline constexpr ChannelMembers<Frame, std::vector<float>> kFrameChannels = {
    &Frame::height, &Frame::slope_x, &Frame::slope_z,  &Frame::disp_x,
    &Frame::disp_z, &Frame::disp_xx, &Frame::disp_zz, &Frame::disp_xz};
constexpr const auto& channel_members(const Frame*) { return kFrameChannels; }

// Every field of a frame: its channels, then the Jacobian made of the choppy ones.
inline constexpr auto kFrameFields = [] {
  std::array<std::vector<float> Frame::*, kChannelCount + 1> all{};
  for (std::size_t ch = 0; ch < kChannelCount; ++ch) all[ch] = kFrameChannels[ch];
  all[kChannelCount] = &Frame::jacobian;
  return all;
}();

// What a frame is evaluated with: its channels by group (common/channels.hpp).
struct FrameRequest {
  bool slopes = true;   // exact spectral dh/dx, dh/dz
  bool choppy = false;  // horizontal displacement (scaled by choppiness) and its Jacobian
};

// Whether the request has field i of kFrameFields.
constexpr bool requested(std::size_t field, FrameRequest r) {
  return field < kChannelCount ? carried(kChannels[field], r.slopes, r.choppy) : r.choppy;
}

}  // namespace ocean::sim
