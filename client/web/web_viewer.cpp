// WebViewer: session, timeline and drawing on the browser's thread.
#include "web_viewer.hpp"

#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base64.hpp"
#include "common/json_writer.hpp"
#include "client/render/channel_upload.hpp"
#include "height_hash.hpp"
#include "stream_wire.hpp"
#include "profile.hpp"

namespace ocean::web {

namespace {
constexpr std::size_t kHashesKept = 600;                   // 20 s of a 30 Hz stream
constexpr std::size_t kRecentDecodes = 600;                // the median of the last 20 s
constexpr std::size_t kRecordLimitBytes = 8u << 20;        // a test records seconds, not hours
constexpr double kEyeHeightM = 10.0, kPitchDeg = -6.0;      // the native viewers' default pose
constexpr double kKbpsSampleS = 0.2;                        // KbpsMeter's five samples a second
double median(const std::deque<double>& values) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
}
void keep_recent(std::deque<double>& recent, double ms) {
  recent.push_back(ms);
  if (recent.size() > kRecentDecodes) recent.pop_front();
}
}  // namespace

double WebViewer::now() const { return emscripten_get_now() / 1000.0; }

bool WebViewer::init(std::string& error) {
  render::RendererDesc desc;
  desc.sky_dir = "/sky";  // embedded in the module (--embed-file)
  if (!renderer_.init(desc)) {
    error = renderer_.error();
    return false;
  }
  if (!hud_.init(error) || !hull_renderer_.init(error)) return false;
  camera_.place({0.0, kEyeHeightM, 0.0}, kPitchDeg, 0.0);
  camera_.far_m = std::max(camera_.far_m, renderer_.desc().view_distance_m * 1.6f);
  return true;
}

void WebViewer::place_camera(double x, double y, double z, double pitch_deg, double yaw_deg) {
  camera_.place({x, std::max(1.0, y), z}, pitch_deg, yaw_deg);
}

void WebViewer::connect(const std::string& url, std::uint8_t profile_id) {
  disconnect();
  client::ClientSessionConfig config;
  config.profile_id = profile_id;
  config.transport = wire::Transport::tcp;  // a browser has no UDP; the WebSocket is the TCP path
  config.client_name = "ocean-web";
  client::ClientSessionEvents events;
  events.send_tcp = [this](std::span<const std::uint8_t> bytes) { socket_.send(bytes); };
  events.on_welcome = [this](const protocol::Welcome& welcome) { on_welcome(welcome); };
  events.on_frame = [this](const codec::ReconstructedFrame& frame, Tick tick) { on_frame(frame, tick); };
  events.on_scene_update = [this](const protocol::SceneUpdate& update) { on_scene_update(update); };
  events.on_closed = [this](const std::string& why) { close_reason_ = why; };
  session_ = std::make_unique<client::ClientSession>(config, std::move(events));
  state_ = "connecting";
  close_reason_.clear();
  ++connects_;
  connect_ms_ = emscripten_get_now();
  open_ms_ = welcome_ms_ = first_frame_ms_ = -1.0;
  BrowserSocketEvents socket_events;
  socket_events.on_open = [this] {
    open_ms_ = emscripten_get_now();
    if (session_) session_->start(now());
  };
  socket_events.on_message = [this](std::span<const std::uint8_t> bytes) { on_message(bytes); };
  socket_events.on_closed = [this](const std::string& why) { end_session(why); };
  std::string error;
  if (!socket_.open(url, std::move(socket_events), error)) end_session(error);
}

void WebViewer::disconnect() {
  if (session_ && socket_.is_open()) session_->quit(now());  // Bye goes out before the close
  socket_.close();
  if (session_) end_session("disconnected");
}

void WebViewer::end_session(const std::string& why) {
  if (!session_) return;
  if (close_reason_.empty()) close_reason_ = why;
  session_.reset();
  socket_.close();
  pending_end_.clear();
  state_ = "closed";
  std::fprintf(stderr, "ocean-web: session ended: %s\n", close_reason_.c_str());
}

void WebViewer::on_message(std::span<const std::uint8_t> bytes) {
  if (!session_) return;
  bytes_in_ += bytes.size();
  ++messages_in_;
  if (recording_ && recorded_bytes_ + bytes.size() > kRecordLimitBytes) {
    recording_ = false;  // stop at the first gap: a replay of later messages would lack their baselines
    recording_full_ = true;
  }
  if (recording_) {
    recorded_.emplace_back(bytes.begin(), bytes.end());
    recorded_bytes_ += bytes.size();
  }
  const std::uint64_t before = session_->stats().frames_complete;
  frame_callback_ms_ = 0.0;
  const double t0 = emscripten_get_now();
  session_->on_tcp_message(bytes, now());
  // Verification and decoding; not what on_frame does with the result (jitter buffer, hash).
  const double handled_ms = emscripten_get_now() - t0;
  messages_ms_ += handled_ms;
  const double spent_ms = handled_ms - frame_callback_ms_;
  if (!session_) return;
  const std::uint64_t completed = session_->stats().frames_complete - before;
  if (completed > 0) {  // handling of messages that carry no frame is not decode
    decode_ms_ += spent_ms;
    keep_recent(recent_decode_ms_, spent_ms);
    keep_recent(recent_message_ms_, handled_ms / static_cast<double>(completed));
  }
  if (!pending_end_.empty()) end_session(pending_end_);
  else if (session_->state() == client::ClientSession::State::closed) end_session(session_->close_reason());
}

void WebViewer::on_welcome(const protocol::Welcome& welcome) {
  const Profile* profile = find_profile(welcome.stream.profile_id);
  profile_ = profile ? std::string(profile->name) : "profile " + std::to_string(welcome.stream.profile_id);
  client::FrameTimelineConfig config;
  if (welcome.tick_period_s > 0) config.tick_period_s = welcome.tick_period_s;
  config.send_interval_s = welcome.stream.rate_hz > 0 ? 1.0 / welcome.stream.rate_hz : config.tick_period_s;
  timeline_ = client::FrameTimeline(config);
  ticks_per_frame_ = std::max(1.0, std::round(config.send_interval_s / config.tick_period_s));
  session_frames_ = 0;
  render::StreamLayout layout;
  std::string layout_error;
  if (!render::stream_layout(welcome.stream.grid, welcome.stream.patch_x_m, welcome.stream.patch_z_m,
                             welcome.stream.cascades, welcome.stream.wake, layout, layout_error)) {
    pending_end_ = layout_error;
    return;
  }
  if (layout != layout_) {
    channels_ = {};
    whitecaps_.clear();
    std::string warning;
    if (!render::apply_layout(renderer_, layout, warning)) {
      // Ended once on_tcp_message has returned: the session is still on the stack here.
      pending_end_ = "stream grid " + std::to_string(welcome.stream.grid) + ": " + renderer_.error();
      return;
    }
    if (!warning.empty()) std::fprintf(stderr, "ocean-web: warning: %s\n", warning.c_str());
    layout_ = layout;
    grid_ = welcome.stream.grid;
  }
  sea_.emplace(codec::decoder_config(welcome));
  fleet_ = welcome.vessels;
  tick_period_s_ = welcome.tick_period_s;
  state_ = "streaming";
  welcome_ms_ = emscripten_get_now();
}

void WebViewer::on_scene_update(const protocol::SceneUpdate& update) {
  if (update.vessels) fleet_ = *update.vessels;  // right for earlier ticks too (PROTOCOL.md 8)
}

// The hulls on the frame just blended, at its place on the server's tick axis, as natively: before
// the water is drawn, so water, trails and hulls share the follow camera's pose of this frame.
void WebViewer::pose_vessels(const client::TimelineSample& sample) {
  if (sea_ && tick_period_s_ > 0.0)
    vessels_.update(fleet_, *sea_, codec::surface_fields(channels_), sample.render_tick * tick_period_s_, hulls_, renderer_,
                    camera_);
}

void WebViewer::on_frame(const codec::ReconstructedFrame& frame, Tick tick) {
  const double t0 = emscripten_get_now();
  ++frames_;
  if (session_frames_++ == 0) first_tick_ = last_tick_ = tick;
  first_tick_ = std::min(first_tick_, tick), last_tick_ = std::max(last_tick_, tick);
  timeline_.set_stream_rtt_s(session_ ? session_->stream_rtt_s() : 0.0);
  timeline_.push(frame, tick, now());
  hashes_.push_back({tick, client::hash_heights(frame.height)});
  if (hashes_.size() > kHashesKept) hashes_.pop_front();
  frame_callback_ms_ += emscripten_get_now() - t0;
}

double WebViewer::loss_percent() const {
  if (session_frames_ < 2) return 0.0;
  const double expected = std::floor(static_cast<double>(last_tick_ - first_tick_) / ticks_per_frame_ + 0.5) + 1.0;
  return std::max(0.0, 100.0 * (1.0 - static_cast<double>(session_frames_) / expected));
}

void WebViewer::touches(const std::vector<render::TouchPoint>& down) {
  render::apply_touch_motion(camera_, touch_.update(down));
  if (double_tap_.update(down, now())) vessels_.cycle_follow();
}

void WebViewer::frame(double now_s, int width, int height) {
  const double started_ms = emscripten_get_now();
  // Time inside the calls that issue GL: with a software rasterizer in the browser's GPU process
  // they wait for it, which a phone's GPU does not make them do.
  double gl_ms = 0.0;
  const auto in_gl = [&gl_ms](auto&& call) {
    const double t0 = emscripten_get_now();
    call();
    gl_ms += emscripten_get_now() - t0;
  };
  const double dt = last_frame_s_ > 0.0 ? std::min(now_s - last_frame_s_, 0.25) : 0.0;
  last_frame_s_ = now_s;
  if (session_ && session_->next_due() <= now_s) {
    session_->update(now_s);
    if (session_ && session_->state() == client::ClientSession::State::closed) end_session(session_->close_reason());
  }

  render::FlyInput input = keys_;
  input.look_dx_px = look_dx_, input.look_dy_px = look_dy_;
  look_dx_ = look_dy_ = 0.0;
  render::apply_fly_input(camera_, input, dt);

  const std::size_t samples = layout_.samples();
  const client::TimelineSample sample = timeline_.sample(now_s);
  if (sample.status != client::TimelineSample::Status::empty && samples > 0) {
    client::FrameTimeline::blend(sample, channels_);
    if (channels_.height.size() == samples) {
      if (session_) whitecaps_.set_wind({session_->scene().wind_speed_mps, session_->scene().wind_dir_deg});
      in_gl([&] { render::upload_channels(renderer_, channels_, layout_, whitecaps_, dt); });
      pose_vessels(sample);
      if (first_frame_ms_ < 0.0) first_frame_ms_ = started_ms;  // drawn below, in this animation frame
      ++uploads_;
    }
  }
  if (session_ && session_->state() == client::ClientSession::State::streaming) {
    renderer_.set_overcast(weather_.update(session_->scene().wind_speed_mps, dt));
    renderer_.set_wind_speed(static_cast<float>(session_->scene().wind_speed_mps));
  }
  in_gl([&] {
    renderer_.draw(camera_, width, height, now_s);
    hulls_in_view_ = hull_renderer_.draw(camera_, width, height, hulls_, render::hull_light(renderer_));
  });

  fps_ = fps_meter_.tick(now_s);
  if (now_s - kbps_sampled_s_ >= kKbpsSampleS) {
    kbps_meter_.update(bytes_in_, now_s);
    kbps_sampled_s_ = now_s;
  }
  if (hud_on_) gl_ms += draw_hud(width, height);
  ++rendered_;
  const double frame_work_ms = emscripten_get_now() - started_ms - gl_ms;
  keep_recent(recent_frame_work_ms_, frame_work_ms);
  keep_recent(recent_page_ms_, frame_work_ms + messages_ms_);
  keep_recent(recent_gl_ms_, gl_ms);
  messages_ms_ = 0.0;
}

// The HUD as the native viewer shows it; the milliseconds its GL calls took.
double WebViewer::draw_hud(int width, int height) {
  render::HudStats stats;
  stats.fps = fps_;
  stats.kbps = kbps_meter_.kbps();
  // As the native viewer shows it: the jitter buffer's delay plus half the round trip.
  stats.latency_ms = 1000.0 * (timeline_.adaptive_delay_s() + (session_ ? session_->stats().rtt_smoothed_s / 2.0 : 0.0));
  stats.loss_percent = loss_percent();
  stats.profile = profile_.empty() ? state_ : profile_;
  char extra[160];
  std::snprintf(extra, sizeof extra, "%s  decode %.2f ms/frame  frames %llu", state_.c_str(),
                frames_ ? decode_ms_ / static_cast<double>(frames_) : 0.0, static_cast<unsigned long long>(frames_));
  stats.extra = extra;
  stats.vessels = vessels_.in_view(hulls_in_view_);
  const double t0 = emscripten_get_now();
  hud_.draw(stats, width, height);
  return emscripten_get_now() - t0;
}

std::string WebViewer::report() const {
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.text("state", state_).text("close_reason", close_reason_).text("profile", profile_).integer("grid", grid_);
  json.integer("connects", connects_).integer("messages", messages_in_).integer("bytes", bytes_in_);
  json.integer("frames", frames_).integer("uploads", uploads_).integer("rendered", rendered_);
  json.fixed("decode_ms_per_frame", frames_ ? decode_ms_ / static_cast<double>(frames_) : 0.0, 4);
  json.fixed("decode_ms_median", median(recent_decode_ms_), 4)
      .fixed("page_ms_median", median(recent_frame_work_ms_) + median(recent_message_ms_), 4)
      .fixed("frame_work_ms_median", median(recent_frame_work_ms_), 4)
      .fixed("message_ms_median", median(recent_message_ms_), 4)
      .fixed("page_ms_per_animation_frame_median", median(recent_page_ms_), 4);
  json.fixed("gl_ms_median", median(recent_gl_ms_), 4);
  json.fixed("connect_ms", connect_ms_, 1).fixed("open_ms", open_ms_, 1).fixed("welcome_ms", welcome_ms_, 1);
  json.fixed("first_frame_ms", first_frame_ms_, 1);
  json.boolean("recording_full", recording_full_);
  json.integer("vessels", static_cast<long long>(vessels_.hulls().size()))
      .integer("vessels_in_view", static_cast<long long>(hulls_in_view_.size()));
  const render::DrawStats& draw = renderer_.last_stats();
  json.integer("triangles", draw.triangles).integer("draw_calls", draw.draw_calls).integer("tiles", draw.tiles_drawn);
  json.fixed("fps", fps_, 2).fixed("kbps", kbps_meter_.kbps(), 2).fixed("loss_percent", loss_percent(), 2);
  if (session_) {
    const client::ClientStats& s = session_->stats();
    json.integer("keyframes", s.keyframes_complete).integer("rejected", s.rejected_total()).integer("keyframe_requests", s.keyframe_requests_sent);
  }
  std::string list = "[";
  for (const FrameHash& h : hashes_) {
    char entry[48];
    std::snprintf(entry, sizeof entry, "%s[%lld,\"%016llx\"]", list.size() > 1 ? "," : "",
                  static_cast<long long>(h.tick), static_cast<unsigned long long>(h.hash));
    list += entry;
  }
  json.raw("hashes", list + "]");
  return json.str();
}

std::string WebViewer::recorded_messages() const {
  std::string out;
  for (const auto& message : recorded_) out += base64_encode(message) + "\n";
  return out;
}

}  // namespace ocean::web
