// NetworkThread: the io_context thread, its frame and Welcome handlers, and stats publication.
#include "client/viewer/network_thread.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <asio/post.hpp>
#include <asio/steady_timer.hpp>

#include "client/viewer/thread_cpu_clock.hpp"
#include "frame_recorder.hpp"
#include "stream_wire.hpp"
#include "profile.hpp"
#include "worker_pool.hpp"

namespace ocean::viewer {

namespace {

constexpr auto kPublishPeriod = std::chrono::milliseconds(200);
constexpr double kByeGraceS = 0.15;  // time for the Bye to leave before the io_context stops

std::uint64_t session_bytes(const client::ClientSession& s) { return s.stats().tcp.bytes_in + s.stats().udp.bytes_in; }

}  // namespace

struct NetworkThread::Recording {
  std::optional<client::FrameRecorder> writer;  // every channel and lattice, each frame's tick
  std::optional<Tick> last_tick;  // the files hold frames in tick order
};

NetworkThread::NetworkThread(NetworkThreadConfig config) : config_(std::move(config)) {}

NetworkThread::~NetworkThread() { stop(); }

void NetworkThread::start() {
  if (thread_.joinable()) return;
  stop_requested_ = false;
  thread_ = std::thread([this] { run(); });
}

void NetworkThread::stop() {
  if (!thread_.joinable()) return;
  stop_requested_ = true;
  thread_.join();
}

StreamShape NetworkThread::stream() const {
  std::lock_guard lock(mutex_);
  return stream_;
}

NetworkStats NetworkThread::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

bool NetworkThread::wait_for_first_frame(double timeout_s) const {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (frames_received_.load() == 0) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

void NetworkThread::run() {
  cpu_start_ms_ = thread_cpu_ms();
  recording_ = std::make_unique<Recording>();
  // Cores the renderer does not need decode each frame's transforms side by side (up to four:
  // desktop-choppy has four); the helpers' CPU shows in the process's time, not in cpu_ms.
  WorkerPool decode_pool(WorkerPool::spare_cores(3));
  client::ClientConnectionConfig connection_config = config_.connection;
  if (decode_pool.helpers() > 0)
    connection_config.session.decode_parallel = [&decode_pool](int count, const std::function<void(int)>& job) {
      decode_pool.run(count, job);
    };
  asio::io_context io;
  std::shared_ptr<client::ClientConnection> connection;
  connection = client::ClientConnection::create(
      io, connection_config,
      [this, &connection](const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) {
        const client::ClientSession* session = connection ? connection->session() : nullptr;
        timeline_.push(frame, tick, arrival_s, session ? session->stream_rtt_s() : 0.0);
        on_frame(frame, tick);
      });
  connection->set_on_welcome([this](const protocol::Welcome& welcome) { on_welcome(welcome); });
  connection->set_on_scene_update([this](const protocol::SceneUpdate& update) { on_scene_update(update); });
  connection->set_on_session_end([this](const client::ClientSession& session, const std::string&) { on_session_end(session); });
  connection->start();

  asio::steady_timer timer(io);
  bool stopping = false;
  std::function<void()> arm = [&] {
    timer.expires_after(stopping ? std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(kByeGraceS))
                                 : std::chrono::duration_cast<std::chrono::steady_clock::duration>(kPublishPeriod));
    timer.async_wait([&](std::error_code ec) {
      if (ec) return;
      if (stopping) {
        io.stop();
        return;
      }
      publish(*connection, client::ClientConnection::now_s());
      if (stop_requested_) {
        stopping = true;
        connection->stop();
      }
      arm();
    });
  };
  arm();
  io.run();
  publish(*connection, client::ClientConnection::now_s());
  if (recording_->writer) {
    try {
      recording_->writer->close();
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex_);
      stats_.record_error = e.what();
    }
  }
  recording_.reset();
}

// A session's totals join those of the sessions before it (reconnections keep the statistics).
void NetworkThread::on_session_end(const client::ClientSession& session) {
  bytes_done_ += session_bytes(session);
  if (session_ticks_.any) {
    expected_done_ += std::floor((session_ticks_.last - session_ticks_.first) / ticks_per_frame_ + 0.5) + 1.0;
    received_done_ += static_cast<double>(session_ticks_.received);
  }
  session_ticks_ = {};
}

void NetworkThread::on_welcome(const protocol::Welcome& welcome) {
  const Profile* profile = find_profile(welcome.stream.profile_id);
  const double send_interval = welcome.stream.rate_hz > 0 ? 1.0 / welcome.stream.rate_hz : welcome.tick_period_s;
  ticks_per_frame_ = welcome.tick_period_s > 0 ? std::max(1.0, std::round(send_interval / welcome.tick_period_s)) : 1.0;
  client::FrameTimelineConfig timeline;
  if (welcome.tick_period_s > 0) timeline.tick_period_s = welcome.tick_period_s;
  timeline.send_interval_s = send_interval;
  timeline.interpolation_delay_s = config_.interpolation_delay_s;
  // Before the stream's new shape is published, so the render thread never sees old frames under it.
  timeline_.reset(timeline);
  std::lock_guard lock(mutex_);
  stream_.generation += 1;
  stream_.grid = welcome.stream.grid;
  stream_.patch_x_m = static_cast<float>(welcome.stream.patch_x_m);
  stream_.patch_z_m = static_cast<float>(welcome.stream.patch_z_m);
  stream_.layout_error.clear();
  render::stream_layout(welcome.stream.grid, welcome.stream.patch_x_m, welcome.stream.patch_z_m, welcome.stream.cascades,
                        welcome.stream.wake, stream_.layout, stream_.layout_error);
  stream_.profile = profile ? std::string(profile->name) : "profile-" + std::to_string(welcome.stream.profile_id);
  stream_.lattices = client::stream_lattices(welcome.stream);
  stream_.tick_period_s = welcome.tick_period_s;
  stream_.send_interval_s = send_interval;
  stream_.config = codec::decoder_config(welcome);
  stream_.vessels = welcome.vessels;
  ++stream_.vessels_serial;
}

void NetworkThread::on_scene_update(const protocol::SceneUpdate& update) {
  if (!update.vessels) return;
  std::lock_guard lock(mutex_);
  stream_.vessels = *update.vessels;
  ++stream_.vessels_serial;
}

void NetworkThread::on_frame(const codec::ReconstructedFrame& frame, Tick tick) {
  frames_received_.fetch_add(1);
  if (!session_ticks_.any) session_ticks_ = {true, tick, tick, 0};
  session_ticks_.first = std::min(session_ticks_.first, tick);
  session_ticks_.last = std::max(session_ticks_.last, tick);
  ++session_ticks_.received;
  if (config_.record_path.empty()) return;
  const double t0 = thread_cpu_ms();
  std::lock_guard lock(mutex_);
  try {
    if (!recording_->writer && stats_.record_error.empty()) recording_->writer.emplace(config_.record_path);
    // Every lattice and channel of the stream; a frame of another stream (after a reconnection to
    // another profile) is counted, not recorded.
    if (recording_->writer && (!recording_->last_tick || tick > *recording_->last_tick) &&
        recording_->writer->append(static_cast<std::int64_t>(tick), stream_.lattices, frame)) {
      recording_->last_tick = tick;
      ++stats_.frames_recorded;
    } else {
      ++stats_.frames_not_recorded;
    }
  } catch (const std::exception& e) {
    stats_.record_error = e.what();
    recording_->writer.reset();
  }
  record_ms_ += thread_cpu_ms() - t0;
}

void NetworkThread::publish(const client::ClientConnection& connection, double now) {
  const client::ClientSession* session = connection.session();
  // Once a session ends its bytes are in bytes_done_, but the connection keeps it as session()
  // until the next one starts: only a connected session's bytes are still to be added.
  const bool live = session && connection.connected();
  const std::uint64_t bytes = bytes_done_ + (live ? session_bytes(*session) : 0);
  const double kbps = kbps_.update(bytes, now);
  double expected = expected_done_, received = received_done_;
  if (session_ticks_.any) {
    expected += std::floor((session_ticks_.last - session_ticks_.first) / ticks_per_frame_ + 0.5) + 1.0;
    received += static_cast<double>(session_ticks_.received);
  }
  const double cpu = thread_cpu_ms() - cpu_start_ms_;
  std::lock_guard lock(mutex_);
  stats_.frames_received = frames_received_.load();
  stats_.bytes_in = bytes;
  stats_.kbps = kbps;
  stats_.rtt_ms = session ? session->stats().rtt_smoothed_s * 1e3 : 0.0;
  stats_.loss_pct = expected > 0 ? std::max(0.0, 100.0 * (1.0 - received / expected)) : 0.0;
  stats_.connects = connection.counters().connects;
  stats_.connected = connection.connected();
  stats_.last_close_reason = connection.counters().last_close_reason;
  if (session) {
    using Path = client::ClientSession::Path;
    const client::ClientStats& st = session->stats();
    stats_.chunks_received = st.chunks_received;
    stats_.chunks_rejected = st.codec_rejected_total();
    stats_.messages_rejected = st.rejected_total();
    stats_.keyframe_requests = st.keyframe_requests_sent;
    stats_.path = session->path() == Path::udp ? "udp" : session->path() == Path::udp_proving ? "udp-proving" : "tcp";
    if (session->state() == client::ClientSession::State::streaming) {
      stream_.wind_speed_mps = session->scene().wind_speed_mps;
      stream_.wind_dir_deg = session->scene().wind_dir_deg;
    }
  }
  stats_.record_ms = record_ms_;
  stats_.cpu_ms = cpu - record_ms_;
}

}  // namespace ocean::viewer
