// SyntheticSource: ocean-viewer-local's FrameSource - the synthetic sea (no server) evaluated on
// the render thread at each frame's time and uploaded, on one grid set at init.
#pragma once

#include <optional>
#include <string>

#include "client/viewer/frame_source.hpp"
#include "client/viewer/synthetic_sea.hpp"

namespace ocean::viewer {

struct SyntheticSourceConfig {
  SyntheticSeaParams sea;
  render::RendererDesc renderer;
  CameraPose pose;
  std::optional<double> time_step_s;  // frame i shows time i * step (headless); none: the wall clock
};

class SyntheticSource final : public FrameSource {
 public:
  // Throws std::invalid_argument naming the parameter when the sea's params are out of range.
  explicit SyntheticSource(const SyntheticSourceConfig& config);

  bool init(std::string& error) override;
  double frame_time_s(int frame_index, double elapsed_s) const override;
  bool update(double t_s, std::string& error) override;
  render::HudStats hud_stats(double fps) const override;
  ViewScene& scene() override { return scene_; }

  const render::DrawStats& last_stats() const { return scene_.renderer.last_stats(); }
  double upload_ms_total() const { return upload_ms_total_; }  // render thread, wall clock
  double synth_ms_total() const { return synth_ms_total_; }

 private:
  SyntheticSourceConfig config_;
  SyntheticSea sea_;
  SeaFrame frame_;
  ViewScene scene_;
  double upload_ms_total_ = 0.0, synth_ms_total_ = 0.0;
};

}  // namespace ocean::viewer
