// StreamView: grid changes, blending and upload on the render thread.
#include "client/viewer/stream_view.hpp"

#include "client/render/channel_upload.hpp"
#include "client/viewer/thread_cpu_clock.hpp"

#include <algorithm>
#include <cmath>
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
      foam_.clear();
      ++grid_changes_;
    }
    shape_ = shape;
    sea_.emplace(shape_.config);
  } else if (shape.vessels_serial != shape_.vessels_serial) {
    shape_.vessels = shape.vessels;  // a vessel command: the fleet changed, not the stream
    shape_.vessels_serial = shape.vessels_serial;
  }
  scene_.renderer.set_overcast(weather_.update(shape.wind_speed_mps, now - last_weather_s_));
  last_weather_s_ = now;
  const double t0 = thread_cpu_ms();
  last_ = net.timeline().render(now, channels_);
  const std::size_t samples = shape_.layout.samples();
  if (last_.status == client::TimelineSample::Status::empty || samples == 0 || channels_.height.size() != samples) {
    ++held_;  // the renderer keeps the last upload: the picture holds
    return true;
  }
  render::upload_channels(scene_.renderer, channels_, shape_.layout, foam_, now - last_upload_s_);
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
  const std::vector<client::HullState>& hulls = motion_.update(shape_.vessels, *sea_, codec::surface_fields(channels_), t_s);
  scene_.hulls.clear();
  std::vector<render::FoamTrail> trails;
  for (const client::HullState& h : hulls) {
    trails.push_back(render::foam_trail(h.x_m, h.z_m, h.dir_x, h.dir_z, h.speed_mps, h.hull.length_m, h.hull.beam_m));
    // Hull-local +x (bow), +y (up), +z (starboard) in world axes: heading, then pitch, then roll.
    const glm::vec3 bow(static_cast<float>(h.dir_x), 0.0f, static_cast<float>(h.dir_z));
    const glm::vec3 starboard(-bow.z, 0.0f, bow.x);
    const float cp = std::cos(static_cast<float>(h.pitch_rad)), sp = std::sin(static_cast<float>(h.pitch_rad));
    const float cr = std::cos(static_cast<float>(h.roll_rad)), sr = std::sin(static_cast<float>(h.roll_rad));
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 fwd = cp * bow + sp * up;                   // bow up by the pitch
    const glm::vec3 lifted = -sp * bow + cp * up;
    const glm::vec3 side = cr * starboard - sr * lifted;        // starboard down by the roll
    const glm::vec3 top = sr * starboard + cr * lifted;
    render::HullInstance hull;
    hull.position = {h.x_m, h.heave_m, h.z_m};
    hull.rotation = glm::mat3(fwd, top, side);
    hull.length_m = static_cast<float>(h.hull.length_m);
    hull.beam_m = static_cast<float>(h.hull.beam_m);
    hull.draft_m = static_cast<float>(h.hull.draft_m);
    scene_.hulls.push_back(hull);
  }
  scene_.renderer.set_trails(trails);
  hull_record_.write(frames_posed_++, t_s, hulls);
  const double dt = t_s - last_pose_s_;
  last_pose_s_ = t_s;
  const auto followed = std::find_if(hulls.begin(), hulls.end(), [&](const client::HullState& h) { return h.id == follow_id_; });
  if (followed != hulls.end()) follow_camera(*followed, dt);
  else follow_eased_ = false;
}

// Behind and above the hull, looking past it along its heading; eased (about a second) so a turn
// at a waypoint swings the view round instead of snapping it.
void StreamView::follow_camera(const client::HullState& h, double dt_s) {
  const double back = 2.2 * h.hull.length_m + 15.0, up = 0.5 * h.hull.length_m + 6.0;
  const glm::dvec3 target(h.x_m - back * h.dir_x, h.heave_m + up, h.z_m - back * h.dir_z);
  const float yaw = static_cast<float>(std::atan2(-h.dir_x, -h.dir_z));
  const float pitch = -0.8f * static_cast<float>(std::atan2(up, back));
  render::Camera& camera = scene_.camera;
  if (!follow_eased_ || dt_s <= 0.0 || dt_s > 1.0) {
    camera.position = target;
    camera.yaw_rad = yaw;
  } else {
    const double k = 1.0 - std::exp(-dt_s / 0.8);
    camera.position += (target - camera.position) * k;
    const float turn = std::remainder(yaw - camera.yaw_rad, 2.0f * 3.14159265f);  // the short way round
    camera.yaw_rad += static_cast<float>(k) * turn;
  }
  camera.pitch_rad = pitch;
  follow_eased_ = true;
}

void StreamView::cycle_follow() {
  const std::vector<client::HullState>& hulls = motion_.hulls();
  const auto at = std::find_if(hulls.begin(), hulls.end(), [&](const client::HullState& h) { return h.id == follow_id_; });
  follow_id_ = at == hulls.end() ? (hulls.empty() ? -1 : hulls.front().id) : (at + 1 == hulls.end() ? -1 : (at + 1)->id);
  follow_eased_ = false;
}

std::string StreamView::vessels_in_view() const {
  std::string line;
  char item[64];
  const std::vector<client::HullState>& hulls = motion_.hulls();
  for (const std::size_t i : scene_.hulls_in_view) {
    if (i >= hulls.size() || line.size() > 160) continue;
    std::snprintf(item, sizeof item, "%svessel %u %.1f m/s%s", line.empty() ? "" : ", ", hulls[i].id, hulls[i].speed_mps,
                  hulls[i].id == follow_id_ ? " (following)" : "");
    line += item;
  }
  return line;
}

}  // namespace ocean::viewer
