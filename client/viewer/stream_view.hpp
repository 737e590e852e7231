// StreamView: the render thread's side of the networked viewer - the renderer sized to the current
// stream (set_grid once per Welcome whose grid differs), and per rendered frame the timeline's
// blend of heights and slopes at the render time, uploaded; the picture holds while nothing arrives.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "client/render/foam_memory.hpp"
#include "client/render/weather_light.hpp"
#include "client/viewer/network_thread.hpp"
#include "client/viewer/view_scene.hpp"

namespace ocean::viewer {

class StreamView {
 public:
  bool init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error);
  // Follows a new Welcome, blends the frame of time now and uploads it. False (with error()) only
  // when the renderer refuses the stream's grid.
  bool update(NetworkThread& net, double now);

  ViewScene& scene() { return scene_; }
  render::Renderer& renderer() { return scene_.renderer; }
  render::HudOverlay& hud() { return scene_.hud; }
  render::Camera& camera() { return scene_.camera; }
  const std::string& error() const { return error_; }
  const StreamShape& shape() const { return shape_; }
  const client::RenderedFrame& last_frame() const { return last_; }

  std::uint64_t uploads() const { return uploads_; }
  double upload_cpu_ms() const { return upload_cpu_ms_; }  // blend + upload, render thread CPU
  std::uint64_t grid_changes() const { return grid_changes_; }
  std::uint64_t held_frames() const { return held_; }        // rendered with no new blend (empty timeline)

 private:
  ViewScene scene_;
  StreamShape shape_;
  client::RenderedFrame last_;
  client::FrameChannels channels_;
  render::FoamMemory foam_;
  render::WeatherEase weather_;
  double last_weather_s_ = 0.0;
  double last_upload_s_ = 0.0;
  std::string error_;
  std::uint64_t uploads_ = 0, grid_changes_ = 0, held_ = 0;
  double upload_cpu_ms_ = 0.0;
};

}  // namespace ocean::viewer
