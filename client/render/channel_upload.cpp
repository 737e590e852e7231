#include "client/render/channel_upload.hpp"

namespace ocean::render {

bool stream_layout(int grid, double patch_x_m, double patch_z_m, std::span<const Cascade> cascades,
                   const WakeLattice& wake, StreamLayout& out, std::string& error) {
  out = {};
  if (wake.grid != 0) {
    out.wake = {wake.grid, static_cast<float>(wake.size_m), static_cast<float>(wake.size_m)};
    out.wake_origin_x_m = static_cast<float>(wake.origin_x_m);
    out.wake_origin_z_m = static_cast<float>(wake.origin_z_m);
  }
  if (cascades.empty()) {
    out.tile = {grid, static_cast<float>(patch_x_m), static_cast<float>(patch_z_m)};
    return true;
  }
  if (cascades.size() > 2) {
    error = "the stream has " + std::to_string(cascades.size()) + " cascades; this renderer draws at most two";
    return false;
  }
  const auto lattice = [&](const Cascade& c) {
    return StreamLayout::Lattice{c.grid, static_cast<float>(patch_x_m * c.patch_scale),
                                 static_cast<float>(patch_z_m * c.patch_scale)};
  };
  out.tile = lattice(cascades[0]);
  if (cascades.size() == 2) out.coarse = lattice(cascades[1]);
  return true;
}

bool apply_layout(Renderer& renderer, const StreamLayout& layout, std::string& warning) {
  warning.clear();
  if (!renderer.set_grid(layout.tile.n, layout.tile.patch_x_m, layout.tile.patch_z_m)) return false;
  const bool wake = layout.wake.n > 0 && renderer.wake_supported();
  if (layout.wake.n > 0 && !wake)
    warning = "the vessels' wake is not drawn (" + renderer.coarse_cascade_unsupported() + ")";
  if (!renderer.set_wake_grid(wake ? layout.wake.n : 0, layout.wake.patch_x_m, layout.wake_origin_x_m,
                              layout.wake_origin_z_m))
    return false;
  if (layout.coarse.n > 0 && !renderer.coarse_cascade_supported()) {
    // The waves the tile leaves out are missing, not approximated: say so rather than show nothing.
    warning += std::string(warning.empty() ? "" : "; ") + "the stream's coarse cascade (" + std::to_string(layout.coarse.n) + " x " +
              std::to_string(layout.coarse.n) + " over " + std::to_string(static_cast<int>(layout.coarse.patch_x_m)) +
              " m) is not drawn (" + renderer.coarse_cascade_unsupported() +
              "): the sea shows only the tile's short waves, repeating every " +
              std::to_string(static_cast<int>(layout.tile.patch_x_m)) + " m";
    return renderer.set_coarse_grid(0, 0.0f, 0.0f);
  }
  return renderer.set_coarse_grid(layout.coarse.n, layout.coarse.patch_x_m, layout.coarse.patch_z_m);
}

bool upload_channels(Renderer& renderer, const client::FrameChannels& f, const StreamLayout& layout, Whitecaps& whitecaps,
                     double dt_s) {
  const std::size_t samples = layout.samples();
  const bool slopes = f.slope_x.size() == samples && f.slope_z.size() == samples;
  const bool choppy = f.disp_x.size() == samples && f.disp_z.size() == samples && f.jacobian.size() == samples;
  // The foam lives on the tile: the coarse cascade's long waves barely fold, and the wake's foam
  // is its own.
  const float* jacobian =
      choppy ? whitecaps.shade(f.jacobian, layout.tile.n, layout.tile.patch_x_m, layout.tile.patch_z_m, dt_s).data()
             : nullptr;
  renderer.set_whitecaps(jacobian ? std::optional(whitecaps.shading()) : std::nullopt);
  const auto at = [](const std::vector<float>& v, bool present, std::size_t offset) {
    return present ? v.data() + offset : nullptr;
  };
  if (!renderer.upload_frame(f.height.data(), at(f.slope_x, slopes, 0), at(f.slope_z, slopes, 0),
                             at(f.disp_x, choppy, 0), at(f.disp_z, choppy, 0), jacobian))
    return false;
  const auto streams_at = [&](std::size_t o) {
    return FrameStreams{f.height.data() + o,     at(f.slope_x, slopes, o), at(f.slope_z, slopes, o),
                        at(f.disp_x, choppy, o), at(f.disp_z, choppy, o),  jacobian ? jacobian + o : nullptr};
  };
  const std::size_t coarse_at = static_cast<std::size_t>(layout.tile.n) * layout.tile.n;
  const std::size_t wake_at = coarse_at + static_cast<std::size_t>(layout.coarse.n) * layout.coarse.n;
  if (layout.coarse.n > 0 && renderer.has_coarse_grid() && !renderer.upload_coarse_frame(streams_at(coarse_at)))
    return false;
  return layout.wake.n == 0 || !renderer.has_wake_grid() || renderer.upload_wake_frame(streams_at(wake_at));
}

}  // namespace ocean::render
