// WebViewer: the browser viewer's whole state on the page's one thread - a ClientSession over a
// BrowserSocket, the FrameTimeline jitter buffer, and the renderer, HUD and camera the native
// viewers draw with. The page's JavaScript calls connect/disconnect and reads report(); the
// browser calls frame() once per animation frame.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "browser_socket.hpp"
#include "client/render/camera.hpp"
#include "client/render/camera_controls.hpp"
#include "client/render/channel_upload.hpp"
#include "client/render/whitecaps.hpp"
#include "client/render/weather_light.hpp"
#include "client/render/hud_overlay.hpp"
#include "client/render/hull_renderer.hpp"
#include "client/render/renderer.hpp"
#include "client/render/touch_controls.hpp"
#include "client/viewer/fps_meter.hpp"
#include "client/viewer/kbps_meter.hpp"
#include "client/viewer/vessel_view.hpp"
#include "client_session.hpp"
#include "frame_timeline.hpp"

namespace ocean::web {

// Per-tick fingerprints of the decoded heights, so a test can hold them against a native decoder
// fed the same messages.
struct FrameHash {
  Tick tick = 0;
  std::uint64_t hash = 0;
};

class WebViewer {
 public:
  // Needs the canvas's WebGL 1 context current. False with a reason.
  bool init(std::string& error);
  // profile_id 0: the server's choice. Ends any session first.
  void connect(const std::string& url, std::uint8_t profile_id);
  void disconnect();
  // Keeps each received message (for a test's replay through the native decoder).
  void set_recording(bool on) { recording_ = on; }
  void set_hud(bool on) { hud_on_ = on; }

  // One animation frame: protocol timers, input, the timeline's blend at now, draw.
  void frame(double now_s, int width, int height);

  // Input, gathered by the page's event handlers.
  render::FlyInput& keys() { return keys_; }
  void look(double dx_px, double dy_px) { look_dx_ += dx_px, look_dy_ += dy_px; }
  void touches(const std::vector<render::TouchPoint>& down);
  // The follow camera's next vessel (the V key, a double tap).
  void cycle_follow() { vessels_.cycle_follow(); }
  void set_follow(std::int64_t id) { vessels_.set_follow(id); }
  // Puts the eye at (x, y, z) world metres, turned as the native viewers' --pitch and --yaw.
  void place_camera(double x, double y, double z, double pitch_deg, double yaw_deg);

  // JSON: state, stream, counts, decode ms per frame, fps, and the recent frame hashes.
  std::string report() const;
  // The recorded messages, one base64 line each, in arrival order.
  std::string recorded_messages() const;

 private:
  void on_welcome(const protocol::Welcome& welcome);
  void on_scene_update(const protocol::SceneUpdate& update);
  void pose_vessels(const client::TimelineSample& sample);
  double draw_hud(int width, int height);  // the milliseconds its GL calls took
  void on_frame(const codec::ReconstructedFrame& frame, Tick tick);
  void on_message(std::span<const std::uint8_t> bytes);
  void end_session(const std::string& why);
  double now() const;
  double loss_percent() const;

  render::Renderer renderer_;
  render::HudOverlay hud_;
  render::Camera camera_;
  render::TouchGesture touch_;
  render::DoubleTap double_tap_;
  render::HullRenderer hull_renderer_;
  viewer::VesselView vessels_;
  std::vector<model::VesselTrack> fleet_;          // Welcome.vessels, as SceneUpdates replace them
  std::optional<codec::SurfaceQuery> sea_;         // the stream's lattices
  std::vector<render::HullInstance> hulls_;
  std::vector<std::size_t> hulls_in_view_;
  double tick_period_s_ = 0.0;
  render::FlyInput keys_;
  double look_dx_ = 0.0, look_dy_ = 0.0;
  bool hud_on_ = true;

  BrowserSocket socket_;
  std::unique_ptr<client::ClientSession> session_;
  client::FrameTimeline timeline_;
  client::FrameChannels channels_;
  render::Whitecaps whitecaps_;
  render::WeatherEase weather_;
  std::string state_ = "idle";  // idle, connecting, streaming, closed
  std::string close_reason_;
  std::string pending_end_;  // set inside a session callback; the session ends after it returns
  std::string profile_;
  int grid_ = 0;
  render::StreamLayout layout_;  // the tile and the coarse cascade the renderer is sized to
  std::uint64_t connects_ = 0;

  // Figures for the HUD and report().
  std::uint64_t bytes_in_ = 0, messages_in_ = 0, frames_ = 0, uploads_ = 0, rendered_ = 0;
  double decode_ms_ = 0.0;  // message handling (verify + decode) for the frames counted in frames_
  // The last messages' handling that completed a frame, each on its own: their median is the figure
  // a decode budget is held to (a joining key, which may compute a wake's history, is one of them).
  std::deque<double> recent_decode_ms_;
  double frame_callback_ms_ = 0.0;  // on_frame's own time within the message being handled
  // The page's own cost (issue 38: what transfers to a phone, whose GPU rasterizes): frame()'s
  // JavaScript and WebAssembly outside the calls that issue GL, and apart the handling of each
  // message that completed a frame (on_frame included). Their medians' sum is the cost of a frame
  // at the stream's rate, whatever the rasterizer's: under a software one the page draws half as
  // often as frames arrive and each animation frame handles two, which a phone's GPU does not
  // make it do. Kept too: the cost per animation frame as it falls here (messages since the last
  // one included), and the time inside the GL calls, waiting for the software rasterizer.
  double messages_ms_ = 0.0;
  std::deque<double> recent_frame_work_ms_, recent_message_ms_, recent_page_ms_, recent_gl_ms_;
  // Startup, in the page's milliseconds from navigation (performance.now()); -1 until it happens.
  double connect_ms_ = -1.0, open_ms_ = -1.0, welcome_ms_ = -1.0, first_frame_ms_ = -1.0;
  double last_frame_s_ = 0.0, fps_ = 0.0, kbps_sampled_s_ = 0.0;
  viewer::FpsMeter fps_meter_;    // the native viewers' meters, so the HUDs read alike
  viewer::KbpsMeter kbps_meter_;
  // Loss: frames the ticks say were sent (one per ticks_per_frame_) against frames received.
  Tick first_tick_ = 0, last_tick_ = 0;
  std::uint64_t session_frames_ = 0;
  double ticks_per_frame_ = 1.0;
  std::deque<FrameHash> hashes_;
  bool recording_ = false, recording_full_ = false;
  std::vector<std::vector<std::uint8_t>> recorded_;
  std::size_t recorded_bytes_ = 0;
};

}  // namespace ocean::web
