// upload_channels: a blended moment to the renderer - slopes when the stream has them, and for a
// choppy stream its displacement and the Jacobian through the foam memory, so foam fades. A
// cascaded stream's channels hold the tile's samples and then the coarse cascade's.
#pragma once

#include "client/net/frame_channels.hpp"
#include "client/render/whitecaps.hpp"
#include "client/render/renderer.hpp"
#include "common/cascade.hpp"
#include "common/wake_lattice.hpp"

#include <cstddef>
#include <span>
#include <string>

namespace ocean::render {

// The lattices of a stream as the renderer draws them: the tile, and a coarse cascade (n 0: none).
struct StreamLayout {
  struct Lattice {
    int n = 0;
    float patch_x_m = 0.0f, patch_z_m = 0.0f;
    bool operator==(const Lattice&) const = default;
  };
  Lattice tile, coarse;
  // The vessels' wake (CODEC.md 7.9; n 0: none), its square's corner in the world.
  Lattice wake;
  float wake_origin_x_m = 0.0f, wake_origin_z_m = 0.0f;
  std::size_t samples() const {
    return static_cast<std::size_t>(tile.n) * tile.n + static_cast<std::size_t>(coarse.n) * coarse.n +
           static_cast<std::size_t>(wake.n) * wake.n;
  }
  bool operator==(const StreamLayout&) const = default;
};

// From the Welcome's StreamParams: grid over the patch, or its cascades (at most two: the tile
// and one coarse cascade; false with `error` otherwise), then its wake lattice if it has one.
bool stream_layout(int grid, double patch_x_m, double patch_z_m, std::span<const Cascade> cascades,
                   const WakeLattice& wake, StreamLayout& out, std::string& error);

// set_grid and set_coarse_grid for the layout. A GL that cannot draw the coarse cascade draws the
// tile alone, and `warning` says what is missing from the picture (the client shows it once).
bool apply_layout(Renderer& renderer, const StreamLayout& layout, std::string& warning);

// false when the renderer refuses the frame (see Renderer::error()); the height channel must have
// layout.samples() samples. A choppy frame's whitecaps are drawn as `whitecaps` shades them (at
// the cover of the wind it was given).
bool upload_channels(Renderer& renderer, const client::FrameChannels& frame, const StreamLayout& layout,
                     Whitecaps& whitecaps, double dt_s);

}  // namespace ocean::render
