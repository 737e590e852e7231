// StreamView: the render thread's side of the networked viewer - the renderer sized to the current
// stream (set_grid once per Welcome whose grid differs), and per rendered frame the timeline's
// blend of heights and slopes at the render time, uploaded; the picture holds while nothing arrives.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "client/render/whitecaps.hpp"
#include "client/viewer/hull_record.hpp"
#include "client/render/weather_light.hpp"
#include "client/viewer/network_thread.hpp"
#include "client/viewer/view_scene.hpp"
#include "client/viewer/vessel_view.hpp"

namespace ocean::viewer {

class StreamView {
 public:
  bool init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error);
  // Follows a new Welcome, blends the frame of time now and uploads it. False (with error()) only
  // when the renderer refuses the stream's grid.
  bool update(NetworkThread& net, double now);
  // Every rendered frame's hull poses to this CSV (HullRecord); false with a reason.
  bool record_hulls(const std::string& path, std::string& error) { return hull_record_.open(path, error); }
  const std::vector<client::HullState>& hulls() const { return vessels_.hulls(); }
  // The camera follows vessel `id` from behind and above (-1: free); cycle_follow() moves it to
  // the next vessel present, and after the last back to free flight.
  void set_follow(std::int64_t id) { vessels_.set_follow(id); }
  void cycle_follow() { vessels_.cycle_follow(); }
  // The HUD's line: the vessels drawn in the last frame, with their speed.
  std::string vessels_in_view() const { return vessels_.in_view(scene_.hulls_in_view); }

  ViewScene& scene() { return scene_; }
  const ViewScene& scene() const { return scene_; }
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
  // The vessels present at the render time, posed on the frame just blended, as the scene's hulls.
  void pose_hulls();

  ViewScene scene_;
  StreamShape shape_;
  client::RenderedFrame last_;
  client::FrameChannels channels_;
  render::Whitecaps whitecaps_;
  render::WeatherEase weather_;
  std::optional<codec::SurfaceQuery> sea_;  // the current stream's lattices
  VesselView vessels_;
  HullRecord hull_record_;
  std::uint64_t frames_posed_ = 0;
  double last_weather_s_ = 0.0;
  double last_upload_s_ = 0.0;
  std::string error_;
  std::uint64_t uploads_ = 0, grid_changes_ = 0, held_ = 0;
  double upload_cpu_ms_ = 0.0;
};

}  // namespace ocean::viewer
