// Headless and window front ends of ocean-viewer, and its JSON summary.
#include "fps_meter.hpp"
#include "client/viewer/viewer_run.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

#include "client/render/camera_controls.hpp"
#include "client/render/framebuffer_readback.hpp"
#include "client/render/offscreen_target.hpp"
#include "client/viewer/app_window.hpp"
#include "client/viewer/headless_context.hpp"
#include "client/viewer/png_file.hpp"
#include "client/viewer/stream_view.hpp"
#include "profile.hpp"

namespace ocean::viewer {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

render::RendererDesc renderer_desc(const ViewerOptions& o) {
  render::RendererDesc desc;
  desc.view_distance_m = o.view_distance_m;
  desc.lod0_distance_m = o.lod0_distance_m;
  return desc;
}

CameraPose camera_pose(const ViewerOptions& o) { return {o.eye_height_m, o.pitch_deg, o.yaw_deg}; }

double latency_ms(const StreamView& view, const NetworkStats& net) {
  const double delay_s = view.shape().send_interval_s > 0 ? 3.0 * view.shape().send_interval_s : 0.0;
  return delay_s * 1e3 + net.rtt_ms / 2.0;
}

render::HudStats hud_stats(double fps, const StreamView& view, const NetworkStats& net, double delay_ms) {
  char extra[160];
  std::snprintf(extra, sizeof extra, "%s %s grid %d rx %llu reconnects %llu", net.connected ? "connected" : "reconnecting",
                net.path.c_str(), view.shape().grid, static_cast<unsigned long long>(net.frames_received),
                static_cast<unsigned long long>(net.connects > 0 ? net.connects - 1 : 0));
  return {fps, net.kbps, delay_ms + net.rtt_ms / 2.0, net.loss_pct, view.shape().profile, extra};
}

void fill_summary(ViewerSummary& s, int frames, double seconds, const StreamView& view, NetworkThread& net,
                  double delay_ms) {
  s.frames = frames;
  s.seconds = seconds;
  s.fps = seconds > 0 ? frames / seconds : 0.0;
  s.net = net.stats();
  s.profile = view.shape().profile;
  s.grid = view.shape().grid;
  s.grid_changes = view.grid_changes();
  s.uploads = view.uploads();
  s.held_frames = view.held_frames();
  const client::TimelineCounters tc = net.timeline().counters();
  s.timeline_stalls = tc.stalls;
  s.frames_late = tc.frames_late;
  s.decode_ms_per_frame = frames ? s.net.cpu_ms / frames : 0.0;
  s.upload_ms_per_frame = frames ? view.upload_cpu_ms() / frames : 0.0;
  s.cpu_ms_per_frame = s.decode_ms_per_frame + s.upload_ms_per_frame;
  s.latency_ms = delay_ms + s.net.rtt_ms / 2.0;
}

double interpolation_delay_ms(const ViewerOptions& o, const StreamView& view) {
  if (o.interpolation_delay_s > 0) return o.interpolation_delay_s * 1e3;
  return latency_ms(view, {});
}

// Reasons are free text; JSON strings may not hold quotes, backslashes or control characters.
std::string json_safe(std::string text) {
  for (char& c : text)
    if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = '\'';
  return text;
}

}  // namespace

bool make_network_config(const ViewerOptions& o, NetworkThreadConfig& config, std::string& error) {
  config.connection.host = o.host;
  config.connection.port = o.port;
  config.connection.session.client_name = "ocean-viewer";
  config.connection.session.bandwidth_bps = o.bandwidth_bps;
  if (o.transport == "tcp") {
    config.connection.session.transport = wire::Transport::tcp;
  } else if (o.transport == "udp") {
    config.connection.session.transport = wire::Transport::udp;
  } else {
    error = "--transport must be udp or tcp, got '" + o.transport + "'";
    return false;
  }
  if (!o.profile.empty()) {
    const Profile* p = find_profile(o.profile);
    if (!p) {
      error = "--profile '" + o.profile + "' is unknown; one of:";
      for (const Profile& known : all_profiles()) error.append(" ").append(known.name);
      return false;
    }
    config.connection.session.profile_id = p->id;
  }
  config.interpolation_delay_s = o.interpolation_delay_s;
  config.record_path = o.record_path;
  return true;
}

int run_headless(const ViewerOptions& o, ViewerSummary& summary, std::string& error) {
  NetworkThreadConfig net_config;
  if (!make_network_config(o, net_config, error)) return 1;
  HeadlessContext context;
  if (!context.create(error)) {
    error = "headless GL context: " + error;
    return 1;
  }
  auto view = std::make_unique<StreamView>();
  render::OffscreenTarget target;
  if (!view->init(renderer_desc(o), camera_pose(o), error) || !target.create(o.width, o.height, error)) return 1;
  summary.gl = context.description();

  NetworkThread net(net_config);
  net.start();
  if (!net.wait_for_first_frame(o.first_frame_timeout_s)) {
    const NetworkStats s = net.stats();
    net.stop();
    char buf[256];
    std::snprintf(buf, sizeof buf, "no frame from %s:%s within %.1f s (--first-frame-timeout); connects %llu%s%s",
                  o.host.c_str(), o.port.c_str(), o.first_frame_timeout_s, static_cast<unsigned long long>(s.connects),
                  s.last_close_reason.empty() ? "" : ", last close: ", s.last_close_reason.c_str());
    error = buf;
    std::snprintf(buf, sizeof buf, "; last session: %llu chunks received, %llu refused by the codec, %llu messages rejected, "
                  "%llu keyframe requests", static_cast<unsigned long long>(s.chunks_received),
                  static_cast<unsigned long long>(s.chunks_rejected), static_cast<unsigned long long>(s.messages_rejected),
                  static_cast<unsigned long long>(s.keyframe_requests));
    error += buf;
    return 1;
  }
  const int frames = o.frames > 0 ? o.frames : 300;
  const auto start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    const double now = client::ClientConnection::now_s();
    if (!view->update(net, now)) {
      error = view->error();
      net.stop();
      return 1;
    }
    target.bind();
    view->renderer().draw(view->camera(), o.width, o.height, now);
    if (o.hud) {
      const double elapsed = seconds_since(start);
      view->hud().draw(hud_stats(elapsed > 0 ? (i + 1) / elapsed : 0.0, *view, net.stats(), interpolation_delay_ms(o, *view)),
                       o.width, o.height);
    }
    glFinish();  // count the rasterisation in the frame time, as a swap would
  }
  const double seconds = seconds_since(start);
  const std::uint64_t bytes_before_stop = net.stats().bytes_in;
  net.stop();
  fill_summary(summary, frames, seconds, *view, net, interpolation_delay_ms(o, *view));
  summary.kbps = seconds > 0 ? bytes_before_stop * 8.0 / 1000.0 / seconds : 0.0;
  if (!o.screenshot.empty()) {
    if (!write_png(o.screenshot, o.width, o.height, render::read_framebuffer_rgba(o.width, o.height), error)) return 1;
    summary.screenshot = o.screenshot;
  }
  return 0;
}

int run_window(const ViewerOptions& o, ViewerSummary& summary, std::string& error) {
  NetworkThreadConfig net_config;
  if (!make_network_config(o, net_config, error)) return 1;
  AppWindow window;
  if (!window.open({o.width, o.height, "ocean-viewer", true}, error)) return 1;
  auto view = std::make_unique<StreamView>();
  if (!view->init(renderer_desc(o), camera_pose(o), error)) return 1;
  NetworkThread net(net_config);
  net.start();
  const auto start = Clock::now();
  auto last = start;
  FpsMeter fps_meter;
  int frame = 0;
  while (!window.should_close() && (o.frames <= 0 || frame < o.frames)) {
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    const double fps = fps_meter.tick(std::chrono::duration<double>(now - start).count());
    render::apply_fly_input(view->camera(), window.poll(), dt);
    const double t = client::ClientConnection::now_s();
    if (!view->update(net, t)) {
      error = view->error();
      net.stop();
      return 1;
    }
    int w = 0, h = 0;
    window.framebuffer_size(w, h);
    view->renderer().draw(view->camera(), w, h, t);
    if (window.hud_visible()) view->hud().draw(hud_stats(fps, *view, net.stats(), interpolation_delay_ms(o, *view)), w, h);
    ++frame;
    if (!o.screenshot.empty() && o.frames > 0 && frame == o.frames) {
      if (write_png(o.screenshot, w, h, render::read_framebuffer_rgba(w, h), error))
        summary.screenshot = o.screenshot;
      else
        std::fprintf(stderr, "ocean-viewer: %s\n", error.c_str());
    }
    window.swap();
  }
  const double seconds = seconds_since(start);
  const std::uint64_t bytes = net.stats().bytes_in;
  net.stop();
  fill_summary(summary, frame, seconds, *view, net, interpolation_delay_ms(o, *view));
  summary.kbps = seconds > 0 ? bytes * 8.0 / 1000.0 / seconds : 0.0;
  return 0;
}

std::string summary_json(const ViewerSummary& s) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "{\"frames\": %d, \"fps\": %.2f, \"kbps\": %.1f, \"cpu_ms_per_frame\": %.4f, \"decode_ms_per_frame\": %.4f, "
      "\"upload_ms_per_frame\": %.4f, \"profile\": \"%s\", \"grid\": %d, \"frames_received\": %llu, "
      "\"latency_ms\": %.1f, \"rtt_ms\": %.2f, \"loss_pct\": %.2f, \"uploads\": %llu, \"held_frames\": %llu, "
      "\"timeline_stalls\": %llu, \"frames_late\": %llu, \"grid_changes\": %llu, \"connects\": %llu, "
      "\"transport\": \"%s\", \"frames_recorded\": %llu, \"decode_ms_per_received_frame\": %.4f, "
      "\"last_close_reason\": \"%s\", \"seconds\": %.3f, \"screenshot\": \"%s\", \"gl\": \"%s\"}",
      s.frames, s.fps, s.kbps, s.cpu_ms_per_frame, s.decode_ms_per_frame, s.upload_ms_per_frame, s.profile.c_str(),
      s.grid, static_cast<unsigned long long>(s.net.frames_received), s.latency_ms, s.net.rtt_ms, s.net.loss_pct,
      static_cast<unsigned long long>(s.uploads), static_cast<unsigned long long>(s.held_frames),
      static_cast<unsigned long long>(s.timeline_stalls), static_cast<unsigned long long>(s.frames_late),
      static_cast<unsigned long long>(s.grid_changes), static_cast<unsigned long long>(s.net.connects),
      s.net.path.c_str(), static_cast<unsigned long long>(s.net.frames_recorded),
      s.net.frames_received ? s.net.cpu_ms / s.net.frames_received : 0.0, json_safe(s.net.last_close_reason).c_str(), s.seconds, s.screenshot.c_str(),
      s.gl.c_str());
  return buf;
}

}  // namespace ocean::viewer
