// StreamView: grid changes, blending and upload on the render thread.
#include "client/viewer/stream_view.hpp"

#include "client/render/channel_upload.hpp"
#include "client/viewer/thread_cpu_clock.hpp"

namespace ocean::viewer {

bool StreamView::init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error) {
  return scene_.init(desc, pose, error);
}

bool StreamView::update(NetworkThread& net, double now) {
  const StreamShape shape = net.stream();
  if (shape.generation != shape_.generation) {
    const bool same_grid = shape.grid == shape_.grid && shape.patch_x_m == shape_.patch_x_m &&
                           shape.patch_z_m == shape_.patch_z_m;
    if (!same_grid && shape.grid > 0) {
      if (!scene_.renderer.set_grid(shape.grid, shape.patch_x_m, shape.patch_z_m)) {
        error_ = "stream grid " + std::to_string(shape.grid) + ": " + scene_.renderer.error();
        return false;
      }
      // The old frame's samples do not fit the new grid: nothing is shown until a frame of it arrives.
      channels_ = {};
      foam_.clear();
      ++grid_changes_;
    }
    shape_ = shape;
  }
  scene_.renderer.set_overcast(weather_.update(shape.wind_speed_mps, now - last_weather_s_));
  last_weather_s_ = now;
  const double t0 = thread_cpu_ms();
  last_ = net.timeline().render(now, channels_);
  const std::size_t samples = static_cast<std::size_t>(shape_.grid) * shape_.grid;
  if (last_.status == client::TimelineSample::Status::empty || samples == 0 || channels_.height.size() != samples) {
    ++held_;  // the renderer keeps the last upload: the picture holds
    return true;
  }
  render::upload_channels(scene_.renderer, channels_, samples, foam_, now - last_upload_s_);
  last_upload_s_ = now;
  upload_cpu_ms_ += thread_cpu_ms() - t0;
  ++uploads_;
  return true;
}

}  // namespace ocean::viewer
