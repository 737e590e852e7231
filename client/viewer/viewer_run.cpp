// ocean-viewer's FrameSource over the network, its two front ends and its JSON summary.
#include "client/viewer/viewer_run.hpp"

#include <cstdio>
#include <memory>

#include "client/viewer/stream_view.hpp"
#include "client/viewer/viewer_loops.hpp"
#include "common/json_writer.hpp"
#include "profile.hpp"

namespace ocean::viewer {

namespace {

constexpr int kHeadlessDefaultFrames = 300;

double latency_ms(const StreamView& view, const NetworkStats& net) {
  const double delay_s = view.shape().send_interval_s > 0 ? 3.0 * view.shape().send_interval_s : 0.0;
  return delay_s * 1e3 + net.rtt_ms / 2.0;
}

double interpolation_delay_ms(const ViewerOptions& o, const StreamView& view) {
  if (o.interpolation_delay_s > 0) return o.interpolation_delay_s * 1e3;
  return latency_ms(view, {});
}

std::string no_first_frame_reason(const ViewerOptions& o, const NetworkStats& s) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "no frame from %s:%s within %.1f s (--first-frame-timeout); connects %llu%s%s",
                o.host.c_str(), o.port.c_str(), o.first_frame_timeout_s, static_cast<unsigned long long>(s.connects),
                s.last_close_reason.empty() ? "" : ", last close: ", s.last_close_reason.c_str());
  std::string reason = buf;
  std::snprintf(buf, sizeof buf, "; last session: %llu chunks received, %llu refused by the codec, %llu messages rejected, "
                "%llu keyframe requests", static_cast<unsigned long long>(s.chunks_received),
                static_cast<unsigned long long>(s.chunks_rejected), static_cast<unsigned long long>(s.messages_rejected),
                static_cast<unsigned long long>(s.keyframe_requests));
  return reason + buf;
}

// The stream an ocean-server sends: received on the NetworkThread, blended and uploaded by the
// StreamView at each frame's time on the connection's clock.
class NetworkSource final : public FrameSource {
 public:
  NetworkSource(const ViewerOptions& options, NetworkThreadConfig config) : options_(options), net_(std::move(config)) {}

  bool init(std::string& error) override {
    if (!view_.init(options_.renderer_desc(), options_.camera_pose(), error)) return false;
    view_.set_follow(options_.follow_id);
    return options_.record_hulls_path.empty() || view_.record_hulls(options_.record_hulls_path, error);
  }
  void cycle_follow() override { view_.cycle_follow(); }
  void start() override { net_.start(); }
  bool wait_for_first_frame(std::string& error) override {
    if (net_.wait_for_first_frame(options_.first_frame_timeout_s)) return true;
    error = no_first_frame_reason(options_, net_.stats());
    return false;
  }
  double frame_time_s(int, double) const override { return client::ClientConnection::now_s(); }
  bool update(double t_s, std::string& error) override {
    if (view_.update(net_, t_s)) return true;
    error = view_.error();
    return false;
  }
  render::HudStats hud_stats(double fps) const override;
  void stop() override {
    if (stopped_) return;
    bytes_before_stop_ = net_.stats().bytes_in;  // what arrived while frames were rendered
    net_.stop();
    stopped_ = true;
  }
  ViewScene& scene() override { return view_.scene(); }

  void fill_summary(ViewerSummary& summary, const LoopResult& loop);

 private:
  const ViewerOptions& options_;
  NetworkThread net_;
  StreamView view_;
  bool stopped_ = false;
  std::uint64_t bytes_before_stop_ = 0;
};

render::HudStats NetworkSource::hud_stats(double fps) const {
  const NetworkStats net = net_.stats();
  char extra[224];
  // Not connected: say why the last session ended ("connection refused", "server_full: ..."),
  // so a viewer with no server does not just show the sky.
  const std::string state = net.connected ? "connected"
                            : net.last_close_reason.empty() ? "connecting"
                                                            : "reconnecting (" + net.last_close_reason.substr(0, 60) + ")";
  std::snprintf(extra, sizeof extra, "%s %s grid %d rx %llu reconnects %llu", state.c_str(),
                net.path.c_str(), view_.shape().grid, static_cast<unsigned long long>(net.frames_received),
                static_cast<unsigned long long>(net.connects > 0 ? net.connects - 1 : 0));
  const double delay_ms = interpolation_delay_ms(options_, view_);
  return {fps, net.kbps, delay_ms + net.rtt_ms / 2.0, net.loss_pct, view_.shape().profile, extra, view_.vessels_in_view()};
}

void NetworkSource::fill_summary(ViewerSummary& s, const LoopResult& loop) {
  const int frames = loop.frames;
  s.frames = frames;
  s.seconds = loop.seconds;
  s.fps = loop.seconds > 0 ? frames / loop.seconds : 0.0;
  s.kbps = loop.seconds > 0 ? bytes_before_stop_ * 8.0 / 1000.0 / loop.seconds : 0.0;
  s.net = net_.stats();
  s.profile = view_.shape().profile;
  s.grid = view_.shape().grid;
  s.grid_changes = view_.grid_changes();
  s.uploads = view_.uploads();
  s.held_frames = view_.held_frames();
  s.vessels = view_.hulls().size();
  s.vessels_in_view = view_.scene().hulls_in_view.size();
  const client::TimelineCounters tc = net_.timeline().counters();
  s.timeline_stalls = tc.stalls;
  s.frames_late = tc.frames_late;
  s.decode_ms_per_frame = frames ? s.net.cpu_ms / frames : 0.0;
  s.upload_ms_per_frame = frames ? view_.upload_cpu_ms() / frames : 0.0;
  s.cpu_ms_per_frame = s.decode_ms_per_frame + s.upload_ms_per_frame;
  s.latency_ms = interpolation_delay_ms(options_, view_) + s.net.rtt_ms / 2.0;
  if (loop.screenshot_written) s.screenshot = options_.screenshot;
  s.gl = loop.gl;
}

LoopSettings loop_settings(const ViewerOptions& o) {
  return {"ocean-viewer", o.width, o.height, o.headless && o.frames <= 0 ? kHeadlessDefaultFrames : o.frames,
          o.screenshot, o.hud};
}

using LoopFunction = int (*)(FrameSource&, const LoopSettings&, LoopResult&, std::string&);

int run_with(LoopFunction loop, const ViewerOptions& o, ViewerSummary& summary, std::string& error) {
  NetworkThreadConfig net_config;
  if (!make_network_config(o, net_config, error)) return 1;
  auto source = std::make_unique<NetworkSource>(o, std::move(net_config));
  LoopResult result;
  const int code = loop(*source, loop_settings(o), result, error);
  if (code == 0) source->fill_summary(summary, result);
  return code;
}

}  // namespace

bool make_network_config(const ViewerOptions& o, NetworkThreadConfig& config, std::string& error) {
  config.connection.host = o.host;
  config.connection.port = o.port;
  config.connection.servers = o.servers;
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
  const int code = run_with(run_headless_loop, o, summary, error);
  if (code != kExitNoServer) return code;
  // A server that answered with an Error refused us; one that never answered is unreachable.
  for (const char* refusal : {"profile_unavailable", "server_full", "unauthorized", "unknown_version"})
    if (error.find(refusal) != std::string::npos) return kExitRefused;
  return code;
}

int run_window(const ViewerOptions& o, ViewerSummary& summary, std::string& error) {
  return run_with(run_window_loop, o, summary, error);
}

std::string summary_json(const ViewerSummary& s) {
  common::JsonWriter json;
  json.integer("frames", s.frames).fixed("fps", s.fps, 2).fixed("kbps", s.kbps, 1);
  json.fixed("cpu_ms_per_frame", s.cpu_ms_per_frame, 4).fixed("decode_ms_per_frame", s.decode_ms_per_frame, 4);
  json.fixed("upload_ms_per_frame", s.upload_ms_per_frame, 4).text("profile", s.profile).integer("grid", s.grid);
  json.integer("frames_received", s.net.frames_received).fixed("latency_ms", s.latency_ms, 1);
  json.fixed("rtt_ms", s.net.rtt_ms, 2).fixed("loss_pct", s.net.loss_pct, 2).integer("uploads", s.uploads);
  json.integer("held_frames", s.held_frames).integer("timeline_stalls", s.timeline_stalls);
  json.integer("vessels", s.vessels).integer("vessels_in_view", s.vessels_in_view);
  json.integer("frames_late", s.frames_late).integer("grid_changes", s.grid_changes).integer("connects", s.net.connects);
  json.text("transport", s.net.path).integer("frames_recorded", s.net.frames_recorded);
  json.fixed("decode_ms_per_received_frame", s.net.frames_received ? s.net.cpu_ms / s.net.frames_received : 0.0, 4);
  json.text("last_close_reason", s.net.last_close_reason).fixed("seconds", s.seconds, 3);
  json.text("screenshot", s.screenshot).text("gl", s.gl);
  return json.str();
}

}  // namespace ocean::viewer
