// NetworkThread: the viewer's network side on its own thread - an io_context running one
// ClientConnection (reconnecting with backoff), pushing every received frame into a SharedTimeline
// for the render thread, optionally recording heights to .npy, and publishing stats and the
// current stream's shape (per Welcome) under a mutex.
#pragma once

#include "tick.hpp"

#include "client/render/channel_upload.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "client/viewer/kbps_meter.hpp"
#include "client_connection.hpp"
#include "shared_timeline.hpp"

namespace ocean::viewer {

struct NetworkThreadConfig {
  client::ClientConnectionConfig connection;
  double interpolation_delay_s = 0.0;  // 0: FrameTimeline's default (three send intervals)
  std::string record_path;             // empty: no recording
};

// The stream the server welcomed us to; generation grows with every Welcome.
struct StreamShape {
  std::uint64_t generation = 0;
  int grid = 0;
  float patch_x_m = 0.0f, patch_z_m = 0.0f;
  render::StreamLayout layout;  // the tile and the coarse cascade, from the Welcome
  std::string layout_error;     // why the renderer cannot draw the stream, if it cannot
  std::string profile;
  std::vector<int> lattices;  // the sizes of the frames' lattices, in order
  double tick_period_s = 0.0;
  double send_interval_s = 0.0;
  double wind_speed_mps = 0.0;  // of the newest scene announced: the weather's light and the foam follow it
  double wind_dir_deg = 0.0;
  codec::StreamConfig config;   // the lattices, for asking the frames where the water is
  // The fleet forcing the wake (Welcome.vessels, replaced by each SceneUpdate that carries one:
  // the new list is right for earlier ticks too, PROTOCOL.md 8); its serial grows with each.
  std::vector<model::VesselTrack> vessels;
  std::uint64_t vessels_serial = 0;
};

struct NetworkStats {
  std::uint64_t frames_received = 0;
  std::uint64_t bytes_in = 0;         // TCP + UDP, every session
  double kbps = 0.0;                  // over the last second or so
  double rtt_ms = 0.0;                // smoothed, 0 until the first Pong
  double loss_pct = 0.0;              // frames never received among those the ticks say were sent
  std::uint64_t connects = 0;
  bool connected = false;
  std::string path;                   // "tcp", "udp", "udp-proving"
  double cpu_ms = 0.0;                // network thread CPU (receive, verify, decode), recording and decode helpers excluded
  double record_ms = 0.0;             // network thread CPU spent writing the recording
  std::uint64_t frames_recorded = 0;
  std::uint64_t frames_not_recorded = 0;  // a later session's grid differed from the recording's
  std::string record_error;
  std::string last_close_reason;
  // The current session's protocol counters, for telling a quiet server from a refused stream.
  std::uint64_t chunks_received = 0, chunks_rejected = 0, messages_rejected = 0, keyframe_requests = 0;
};

class NetworkThread {
 public:
  explicit NetworkThread(NetworkThreadConfig config);
  ~NetworkThread();  // stops
  NetworkThread(const NetworkThread&) = delete;
  NetworkThread& operator=(const NetworkThread&) = delete;

  void start();
  // Says Bye, stops reconnecting, joins the thread, and closes the recording.
  void stop();

  client::SharedTimeline& timeline() { return timeline_; }
  StreamShape stream() const;
  NetworkStats stats() const;
  std::uint64_t frames_received() const { return frames_received_.load(); }
  // True once a frame has arrived; false after timeout_s without one.
  bool wait_for_first_frame(double timeout_s) const;

 private:
  void run();
  void on_welcome(const protocol::Welcome& welcome);
  void on_scene_update(const protocol::SceneUpdate& update);
  void on_session_end(const client::ClientSession& session);
  void on_frame(const codec::ReconstructedFrame& frame, Tick tick);
  void publish(const client::ClientConnection& connection, double now);

  NetworkThreadConfig config_;
  client::SharedTimeline timeline_;
  std::thread thread_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<std::uint64_t> frames_received_{0};

  // Network-thread state.
  struct SessionTicks {
    bool any = false;
    Tick first = 0, last = 0;
    std::uint64_t received = 0;
  } session_ticks_;
  double expected_done_ = 0.0, received_done_ = 0.0;  // frames of ended sessions (for loss)
  std::uint64_t bytes_done_ = 0;                      // bytes of ended sessions
  KbpsMeter kbps_;
  double cpu_start_ms_ = 0.0, record_ms_ = 0.0;
  double ticks_per_frame_ = 1.0;
  struct Recording;
  std::unique_ptr<Recording> recording_;

  mutable std::mutex mutex_;  // guards stream_ and stats_
  StreamShape stream_;
  NetworkStats stats_;
};

}  // namespace ocean::viewer
