// upload_channels: a blended moment to the renderer - slopes when the stream has them, and for a
// choppy stream its displacement and the Jacobian through the foam memory, so foam fades.
#pragma once

#include "client/net/frame_channels.hpp"
#include "client/render/foam_memory.hpp"
#include "client/render/renderer.hpp"

#include <cstddef>

namespace ocean::render {

// false when the renderer refuses the frame (see Renderer::error()); `samples` is grid * grid and
// the height channel must have that many.
bool upload_channels(Renderer& renderer, const client::FrameChannels& frame, std::size_t samples, FoamMemory& foam,
                     double dt_s);

}  // namespace ocean::render
