#include "load_run.hpp"

#include "frame_timeline.hpp"

#include <asio/io_context.hpp>
#include <asio/steady_timer.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "client_figures.hpp"
#include "client_links.hpp"
#include "frame_recorder.hpp"
#include "frame_verdict.hpp"
#include "ground_truth.hpp"
#include "latency_histogram.hpp"
#include "process_cpu.hpp"
#include "profile.hpp"
#include "scenario.hpp"
#include "sim_client.hpp"
#include "stream_facts.hpp"

namespace ocean::loadtest {
namespace {

double unix_now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

class Driver {
 public:
  explicit Driver(const LoadtestOptions& o) : o_(o), clients_(static_cast<std::size_t>(o.clients)), tick_timer_(io_), sample_timer_(io_) {}

  LoadRunResult run() {
    LoadRunResult result;
    if (!o_.record_path.empty()) recorder_.emplace(o_.record_path);
    start_steady_ = client::ClientConnection::now_s();
    start_unix_ = unix_now_s();
    cpu_start_ = own_cpu_s();
    server_cpu_start_ = process_cpu_s(o_.server_pid);
    end_steady_ = start_steady_ + o_.ramp_s + o_.duration_s;
    schedule_second(1);
    schedule_sample(1);
    io_.run_for(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(o_.ramp_s + o_.duration_s + 2.0)));
    io_.restart();
    // An overloaded loop may not have reached its last second: end the measurement here.
    if (!measuring_done_) finish();
    // Let the Byes go out, then drop everything.
    io_.run_for(std::chrono::milliseconds(200));
    result.summary = summarize();
    result.series = std::move(series_);
    if (recorder_) {
      try {
        recorder_->close();
      } catch (const std::exception& e) {
        if (record_error_.empty()) record_error_ = std::string("--record: ") + e.what();
      }
    }
    result.error = record_error_;
    if (result.summary.clients_welcomed == 0) {
      // The figures of a run no client took part in are zeros, not a measurement.
      std::string why = clients_.empty() || !clients_[0].connection ? std::string("never started")
                                                                    : clients_[0].connection->counters().last_close_reason;
      result.error = "no client ever connected to " + server_names() + " (client 0: " +
                     (why.empty() ? "no answer" : why) + ")" + (result.error.empty() ? "" : "; " + result.error);
    }
    return result;
  }

 private:
  std::string server_names() const {
    std::string names;
    for (const client::ServerEndpoint& s : o_.servers) names += (names.empty() ? "" : ",") + s.host + ":" + s.port;
    return names;
  }

  struct Clock {
    static double now() { return client::ClientConnection::now_s(); }
  };

  void start_client(std::size_t i) {
    client::ClientConnectionConfig config;
    config.servers = o_.servers;
    config.session.profile_id = find_profile(o_.profile)->id;
    config.session.transport = o_.transport == "tcp" ? wire::Transport::tcp : wire::Transport::udp;
    config.session.client_name = "ocean-loadtest-" + std::to_string(i);
    config.session.bandwidth_bps = o_.bandwidth_bps;
    if (o_.shared_decode) config.session.decode_memo = [this](const codec::StreamConfig& c) { return memo_for(c); };
    auto connection = client::ClientConnection::create(
        io_, config,
        [this, i](const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) { on_frame(i, frame, tick, arrival_s); },
        make_client_links(o_.link, o_.seed + i));
    connection->set_on_welcome([this, i](const protocol::Welcome& w) { on_welcome(i, w); });
    // Scenes arrive ahead of their tick; the truth switches at the same tick as the codec.
    connection->set_on_scene_update([this](const protocol::SceneUpdate& u) {
      if (truth_) truth_->set_scene(u.effective_tick, u.scene);
    });
    connection->set_on_session_end([this, i](const client::ClientSession& s, const std::string&) { clients_[i].end_session(s); });
    SimClient& c = clients_[i];
    c.connection = connection;
    c.started_s = Clock::now();
    c.traffic.sample(c.started_s, 0);
    connection->start();
  }

  codec::DecodeMemo* memo_for(const codec::StreamConfig& config) {
    for (const auto& memo : memos_)
      if (memo->config() == config) return memo.get();
    // Scene changes make new configurations; old memos stop being asked and stay small.
    return memos_.emplace_back(std::make_unique<codec::DecodeMemo>(config)).get();
  }

  // A frame shown by many clients (same shared_id) is compared with the truth once.
  FrameError checked_error(const codec::ReconstructedFrame& frame, Tick tick) {
    if (frame.shared_id != 0)
      if (const auto found = verdicts_.find(frame.shared_id); found != verdicts_.end()) return found->second;
    const sim::Frame& truth = truth_->at(tick, facts_.grid);
    ++truth_checks_;
    const FrameError error = frame_error(frame.height, frame.slope_x, frame.slope_z, truth.height, truth.slope_x, truth.slope_z);
    if (frame.shared_id != 0) {
      verdicts_.emplace(frame.shared_id, error);
      while (verdicts_.size() > 4096) verdicts_.erase(verdicts_.begin());  // ids only grow: the oldest go
    }
    return error;
  }

  void on_welcome(std::size_t i, const protocol::Welcome& w) {
    if (!truth_) {
      facts_ = StreamFacts::from(w);
      truth_.emplace(facts_.tick_rate_hz);
      truth_->set_scene(0, w.scene);
      warn_if_server_differs(w);
    } else {
      truth_->set_scene(w.current_tick, w.scene);
    }
    SimClient& c = clients_[i];
    c.session_ended = false;  // a new session of this connection
    if (!c.welcome_tick) c.welcome_tick = w.current_tick;
    if (!c.tally) c.tally.emplace(facts_.tick_period_s, facts_.interval_ticks);
  }

  void warn_if_server_differs(const protocol::Welcome& w) const {
    const Scenario* scenario = o_.scenario.empty() ? nullptr : find_scenario(o_.scenario);
    if (!scenario) return;
    if (const std::string why = server_mismatch(scenario->server, facts_.tick_rate_hz, w.epoch_unix_ms, unix_now_s()); !why.empty())
      std::fprintf(stderr, "ocean-loadtest: warning: the server does not run as scenario %s needs (%s): %s; "
                   "start it with client/loadtest/local_server.py\n", o_.scenario.c_str(), describe(scenario->server).c_str(), why.c_str());
  }

  Tick end_tick() const { return facts_.tick_at_unix(start_unix_ + o_.ramp_s + o_.duration_s - 1.0); }

  void on_frame(std::size_t i, const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) {
    SimClient& c = clients_[i];
    if (!truth_ || !c.tally || measuring_done_) return;
    // The schedule owes frames up to one second before the end; later ones may still be in flight,
    // and count only as a client's first frame.
    const bool owed = tick <= end_tick();
    if (!owed && c.first_frame_s) return;
    const double now_unix = unix_now_s();
    const FrameError error = checked_error(frame, tick);
    const bool within_bound = within_bounds(error, facts_.bounds);
    if (within_bound && !c.first_frame_s) {
      c.first_frame_s = arrival_s;
      c.traffic.set_first_frame(arrival_s);
    }
    if (!owed) return;
    ClientTally& tally = *c.tally;
    tally.clock().observe(tick, arrival_s);
    FrameOutcome outcome;
    outcome.within_bound = within_bound;
    // The viewer's jitter buffer (FrameTimeline) adds delay on a jittery link; judge by the same.
    const double delay = client::FrameTimeline::adaptive_delay(
        tally.clock(), facts_.interpolation_delay_s, static_cast<double>(facts_.interval_ticks) * facts_.tick_period_s);
    max_delay_s_ = std::max(max_delay_s_, delay);
    outcome.on_time = arrived_on_time(arrival_s, tick, *tally.clock().offset_s(), facts_.tick_period_s, delay);
    if (!tally.record(tick, outcome, error.height_m)) return;
    const double latency = now_unix - (facts_.epoch_s + truth_->time_of(tick));
    latency_all_.add(latency);
    latency_second_.add(latency);
    ++second_frames_;
    if (outcome.within_bound && outcome.on_time) ++second_ok_;
    if (!outcome.within_bound) ++second_bad_;
    if (i == 0 && recorder_ && record_error_.empty() && (!recorded_tick_ || tick > *recorded_tick_)) {
      recorded_tick_ = tick;
      try {
        recorder_->append(tick, facts_.grid, frame.height);
      } catch (const std::exception& e) {
        record_error_ = std::string("--record: ") + e.what();
      }
    }
  }

  // Starts the clients due by now, and once a second prints progress and adds a series row.
  void schedule_second(int second) {
    const double due = start_steady_ + second * 1.0;
    launch_due();
    arm_at(std::min(due, next_launch_time()), [this, second, due] {
      if (Clock::now() + 1e-4 >= due) {
        second_tick(second);
        if (Clock::now() < end_steady_) schedule_second(second + 1);
        else finish();
      } else {
        schedule_second(second);
      }
    });
  }

  // Every 100 ms, each started client's received bytes, for its busiest second (ReceiveRate).
  void schedule_sample(int k) {
    const double due = start_steady_ + k * kSampleS;
    const double wait = std::max(0.0, due - Clock::now());
    sample_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wait)));
    sample_timer_.async_wait([this, k](const std::error_code& ec) {
      if (ec || measuring_done_) return;
      sample_traffic();
      // A loop that fell behind skips the samples it missed instead of bunching them.
      const int next = std::max(k + 1, static_cast<int>(std::floor((Clock::now() - start_steady_) / kSampleS)) + 1);
      schedule_sample(next);
    });
  }

  void sample_traffic() {
    const double now = Clock::now();
    for (std::size_t i = 0; i < launched_; ++i) clients_[i].traffic.sample(now, clients_[i].bytes());
  }

  double next_launch_time() const {
    if (launched_ >= clients_.size()) return std::numeric_limits<double>::infinity();
    return start_steady_ + o_.ramp_s * static_cast<double>(launched_) / static_cast<double>(clients_.size());
  }

  void launch_due() {
    while (launched_ < clients_.size() && next_launch_time() <= Clock::now()) start_client(launched_++);
  }

  template <typename F>
  void arm_at(double steady_s, F&& f) {
    const double wait = std::max(0.0, steady_s - Clock::now());
    tick_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wait)));
    tick_timer_.async_wait([f = std::forward<F>(f)](const std::error_code& ec) {
      if (!ec) f();
    });
  }

  void second_tick(int second) {
    std::uint64_t bytes = 0;
    int connected = 0;
    for (const SimClient& c : clients_) {
      bytes += c.bytes();
      if (c.connection && c.connection->connected()) ++connected;
    }
    SeriesRow row;
    row.t_s = second;
    row.clients = connected;
    row.kbps_mean = connected ? (bytes - last_bytes_) * 8.0 / 1000.0 / connected : 0.0;
    row.ok_pct = second_frames_ ? 100.0 * second_ok_ / second_frames_ : 0.0;
    row.latency_p50_ms = latency_second_.percentile(50) * 1e3;
    row.latency_p99_ms = latency_second_.percentile(99) * 1e3;
    row.bad = second_bad_;
    series_.push_back(row);
    last_bytes_ = bytes;
    second_frames_ = second_ok_ = second_bad_ = 0;
    latency_second_.clear();
    if (o_.progress)
      std::fprintf(stderr, "[%4ds] clients %d/%zu  frames ok %.2f%%  bad %llu  kbps %.1f  p99 %.1f ms\n", second, connected,
                   clients_.size(), row.ok_pct, static_cast<unsigned long long>(row.bad), row.kbps_mean, row.latency_p99_ms);
  }

  void finish() {
    sample_traffic();
    measuring_done_ = true;
    sample_timer_.cancel();
    end_unix_ = unix_now_s();
    end_wall_steady_ = Clock::now();
    cpu_end_ = own_cpu_s();
    server_cpu_end_ = process_cpu_s(o_.server_pid);
    end_bytes_ = end_datagrams_ = 0;
    for (const SimClient& c : clients_) {
      end_bytes_ += c.bytes();
      end_datagrams_ += c.udp_datagrams();
      if (c.connection && c.connection->connected()) ++connected_at_end_;
    }
    for (SimClient& c : clients_)
      if (c.connection) c.connection->stop();
    // Stop once the Byes are out (run() bounds this with run_for).
    arm_at(Clock::now() + 0.2, [this] { io_.stop(); });
  }

  LoadSummary summarize() const {
    LoadSummary s;
    s.clients = o_.clients;
    s.clients_connected = connected_at_end_;
    s.profile = o_.profile;
    s.transport = o_.transport;
    s.link = o_.link_text;
    s.scenario = o_.scenario;
    s.bandwidth_bps = o_.bandwidth_bps;
    const double wall = end_wall_steady_ - start_steady_;
    s.duration_s = wall;
    s.loadtest_cpu_pct = wall > 0 ? 100.0 * (cpu_end_ - cpu_start_) / wall : 0.0;
    if (server_cpu_start_ && server_cpu_end_ && wall > 0) s.server_cpu_pct = 100.0 * (*server_cpu_end_ - *server_cpu_start_) / wall;
    s.error_bound_m = facts_.bounds.height_m;
    s.interpolation_delay_ms = facts_.interpolation_delay_s * 1e3;
    s.interpolation_delay_max_ms = max_delay_s_ * 1e3;
    const Tick last_tick = truth_ ? end_tick() : 0;
    double client_seconds = 0.0;
    std::vector<ClientConnectionFacts> facts(clients_.size());
    for (std::size_t i = 0; i < clients_.size(); ++i) {
      const SimClient& c = clients_[i];
      facts[i] = c.connection_facts();
      c.add_counters_to(s);
      const double started = o_.ramp_s * static_cast<double>(i) / static_cast<double>(clients_.size());
      client_seconds += std::max(0.0, wall - started);
      if (!truth_) continue;
      const Tick start_tick = c.welcome_tick.value_or(facts_.tick_at_unix(start_unix_ + started));
      ClientTally empty(facts_.tick_period_s, facts_.interval_ticks);
      const ClientTally& t = c.tally ? *c.tally : empty;
      const std::uint64_t expected = t.expected(start_tick, last_tick);
      s.frames_expected += expected;
      s.frames_received += t.received();
      s.frames_ok += t.ok();
      s.frames_late += t.late();
      s.frames_bad += t.bad();
      s.stalls += t.stalls();
      s.max_err_m = std::max(s.max_err_m, t.max_error_m());
      if (expected > t.received()) s.frames_lost += expected - t.received();
    }
    if (!truth_) s.frames_expected = 0;
    s.frames_ok_pct = s.frames_expected ? 100.0 * std::min(s.frames_ok, s.frames_expected) / s.frames_expected : 0.0;
    s.kbps_mean = client_seconds > 0 ? end_bytes_ * 8.0 / 1000.0 / client_seconds : 0.0;
    s.kbps_mean_ip = client_seconds > 0 ? (end_bytes_ + kIpUdpHeaderBytes * end_datagrams_) * 8.0 / 1000.0 / client_seconds : 0.0;
    static_cast<ConnectionFigures&>(s) = connection_figures(facts);
    s.latency_p50_ms = latency_all_.percentile(50) * 1e3;
    s.latency_p99_ms = latency_all_.percentile(99) * 1e3;
    s.latency_max_ms = latency_all_.max_s() * 1e3;
    s.truth_evaluations = truth_ ? truth_->evaluations() : 0;
    s.scenes = truth_ ? static_cast<int>(truth_->scenes()) : 0;
    s.truth_checks = truth_checks_;
    for (const auto& memo : memos_) {
      s.decodes_run += memo->counts().misses;
      s.decodes_shared += memo->counts().hits;
    }
    return s;
  }

  const LoadtestOptions& o_;
  asio::io_context io_;
  std::vector<SimClient> clients_;
  asio::steady_timer tick_timer_, sample_timer_;
  static constexpr double kSampleS = 0.1;
  static constexpr int kIpUdpHeaderBytes = 28;  // IPv4 20 + UDP 8, per datagram
  std::size_t launched_ = 0;
  std::optional<GroundTruth> truth_;
  StreamFacts facts_;
  LatencyHistogram latency_all_, latency_second_;
  std::uint64_t second_frames_ = 0, second_ok_ = 0, second_bad_ = 0, last_bytes_ = 0, end_bytes_ = 0, end_datagrams_ = 0;
  std::vector<SeriesRow> series_;
  double start_steady_ = 0.0, end_steady_ = 0.0, end_wall_steady_ = 0.0, start_unix_ = 0.0, end_unix_ = 0.0;
  double cpu_start_ = 0.0, cpu_end_ = 0.0;
  std::optional<double> server_cpu_start_, server_cpu_end_;
  bool measuring_done_ = false;
  double max_delay_s_ = 0.0;  // the largest jitter-adapted delay any client's frame was judged by
  int connected_at_end_ = 0;
  std::string record_error_;
  std::optional<client::FrameRecorder> recorder_;
  std::optional<Tick> recorded_tick_;  // client 0's file holds frames in tick order
  std::vector<std::unique_ptr<codec::DecodeMemo>> memos_;
  std::map<std::uint64_t, FrameError> verdicts_;  // by ReconstructedFrame::shared_id
  std::uint64_t truth_checks_ = 0;
};

}  // namespace

LoadRunResult run_load(const LoadtestOptions& options) { return Driver(options).run(); }

}  // namespace ocean::loadtest
