// StreamView: grid changes, blending and upload on the render thread.
#include "client/viewer/stream_view.hpp"

#include "client/render/channel_upload.hpp"
#include "client/viewer/thread_cpu_clock.hpp"

#include <cstdio>
#include <string>

namespace ocean::viewer {

bool StreamView::init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error) {
  return scene_.init(desc, pose, error);
}

bool StreamView::update(NetworkThread& net, double now) {
  const StreamShape shape = net.stream();
  if (shape.generation != shape_.generation) {
    if (!shape.layout_error.empty()) {
      error_ = "stream grid " + std::to_string(shape.grid) + ": " + shape.layout_error;
      return false;
    }
    if (shape.layout != shape_.layout && shape.grid > 0) {
      std::string warning;
      if (!render::apply_layout(scene_.renderer, shape.layout, warning)) {
        error_ = "stream grid " + std::to_string(shape.grid) + ": " + scene_.renderer.error();
        return false;
      }
      if (!warning.empty()) std::fprintf(stderr, "ocean-viewer: warning: %s\n", warning.c_str());
      // The old frame's samples do not fit the new grid: nothing is shown until a frame of it arrives.
      channels_ = {};
      whitecaps_.clear();
      ++grid_changes_;
    }
    shape_ = shape;
    sea_.emplace(shape_.config);
  } else if (shape.vessels_serial != shape_.vessels_serial) {
    shape_.vessels = shape.vessels;  // a vessel command: the fleet changed, not the stream
    shape_.vessels_serial = shape.vessels_serial;
  }
  scene_.renderer.set_overcast(weather_.update(shape.wind_speed_mps, now - last_weather_s_));
  scene_.renderer.set_wind_speed(static_cast<float>(shape.wind_speed_mps));
  whitecaps_.set_wind({shape.wind_speed_mps, shape.wind_dir_deg});
  last_weather_s_ = now;
  const double t0 = thread_cpu_ms();
  last_ = net.timeline().render(now, channels_);
  const std::size_t samples = shape_.layout.samples();
  if (last_.status == client::TimelineSample::Status::empty || samples == 0 || channels_.height.size() != samples) {
    ++held_;  // the renderer keeps the last upload: the picture holds
    return true;
  }
  render::upload_channels(scene_.renderer, channels_, shape_.layout, whitecaps_, now - last_upload_s_);
  pose_hulls();
  last_upload_s_ = now;
  upload_cpu_ms_ += thread_cpu_ms() - t0;
  ++uploads_;
  return true;
}

void StreamView::pose_hulls() {
  if (!sea_ || shape_.tick_period_s <= 0.0) return;
  // Track time is the server's tick over its rate (CODEC.md 7.9), here the blend's own tick.
  const double t_s = last_.render_tick * shape_.tick_period_s;
  hull_record_.write(frames_posed_++, t_s,
                     vessels_.update(shape_.vessels, *sea_, codec::surface_fields(channels_), t_s, scene_.hulls,
                                     scene_.renderer, scene_.camera));
}

}  // namespace ocean::viewer
