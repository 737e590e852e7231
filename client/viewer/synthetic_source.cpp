// SyntheticSource: evaluate, upload and describe the synthetic sea.
#include "client/viewer/synthetic_source.hpp"

#include <chrono>
#include <cstdio>

namespace ocean::viewer {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string tiles_text(const render::DrawStats& s) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "tiles %d (lod %d/%d/%d/%d/%d/%d) tris %lld", s.tiles_drawn, s.tiles_per_level[0],
                s.tiles_per_level[1], s.tiles_per_level[2], s.tiles_per_level[3], s.tiles_per_level[4],
                s.tiles_per_level[5], static_cast<long long>(s.triangles));
  return buf;
}

}  // namespace

SyntheticSource::SyntheticSource(const SyntheticSourceConfig& config) : config_(config), sea_(config.sea) {}

bool SyntheticSource::init(std::string& error) {
  if (!scene_.init(config_.renderer, config_.pose, error)) return false;
  if (!scene_.renderer.set_grid(config_.sea.n, config_.sea.patch_m, config_.sea.patch_m)) {
    error = scene_.renderer.error();
    return false;
  }
  return true;
}

double SyntheticSource::frame_time_s(int frame_index, double elapsed_s) const {
  return config_.time_step_s ? frame_index * *config_.time_step_s : elapsed_s;
}

bool SyntheticSource::update(double t_s, std::string& /*error*/) {
  auto t0 = Clock::now();
  sea_.evaluate(t_s, frame_);
  synth_ms_total_ += ms_since(t0);
  t0 = Clock::now();
  const bool choppy = !frame_.disp_x.empty();
  scene_.renderer.upload_frame(frame_.height.data(), frame_.slope_x.data(), frame_.slope_z.data(),
                               choppy ? frame_.disp_x.data() : nullptr, choppy ? frame_.disp_z.data() : nullptr,
                               choppy ? frame_.jacobian.data() : nullptr);
  upload_ms_total_ += ms_since(t0);
  return true;
}

render::HudStats SyntheticSource::hud_stats(double fps) const {
  return {fps, 0.0, 0.0, 0.0, "local-synthetic", tiles_text(scene_.renderer.last_stats()), ""};
}

}  // namespace ocean::viewer
