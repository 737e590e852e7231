#include "load_shard.hpp"

#include "frame_timeline.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "client_links.hpp"
#include "process_cpu.hpp"
#include "profile.hpp"
#include "scenario.hpp"

namespace ocean::loadtest {
namespace {

double unix_now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

double steady_now() { return client::ClientConnection::now_s(); }

std::size_t share_of(int clients, int index, int count) {
  return static_cast<std::size_t>((clients - index + count - 1) / count);
}

}  // namespace

LoadShard::LoadShard(RunShared& shared, int index, int count)
    : shared_(shared),
      o_(shared.options),
      index_(index),
      count_(count),
      clients_(share_of(shared.options.clients, index, count)),
      tick_timer_(io_),
      sample_timer_(io_) {}

void LoadShard::run() {
  if (!o_.record_path.empty() && index_ == 0) recorder_.emplace(o_.record_path);
  schedule_second(1);
  schedule_sample(1);
  io_.run_for(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(shared_.end_steady + 2.0 - steady_now())));
  io_.restart();
  // An overloaded loop may not have reached its last second: end the measurement here.
  if (!measuring_done_) finish();
  // Let the Byes go out, then drop everything.
  io_.run_for(std::chrono::milliseconds(200));
  if (recorder_) {
    try {
      recorder_->close();
    } catch (const std::exception& e) {
      if (record_error_.empty()) record_error_ = std::string("--record: ") + e.what();
    }
  }
}

std::string LoadShard::first_close_reason() const {
  return clients_.empty() || !clients_[0].connection ? std::string("never started") : clients_[0].connection->counters().last_close_reason;
}

void LoadShard::start_client(std::size_t k) {
  const std::size_t i = global_index(k);
  client::ClientConnectionConfig config;
  config.servers = o_.servers;
  config.session.profile_id = find_profile(o_.profile)->id;
  config.session.transport = o_.transport == "udp" ? wire::Transport::udp : wire::Transport::tcp;
  config.websocket = o_.transport == "ws";  // --server names the --ws-listen port then
  config.websocket_seed = o_.seed + i;
  config.session.client_name = "ocean-loadtest-" + std::to_string(i);
  config.session.bandwidth_bps = o_.bandwidth_bps;
  if (o_.shared_decode) config.session.decode_memo = [this](const codec::StreamConfig& c) { return memo_for(c); };
  auto connection = client::ClientConnection::create(
      io_, config,
      [this, k](const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) { on_frame(k, frame, tick, arrival_s); },
      make_client_links(o_.link, o_.seed + i, o_.transport != "udp"));
  connection->set_on_welcome([this, k](const protocol::Welcome& w) { on_welcome(k, w); });
  // Scenes arrive ahead of their tick; the truth switches at the same tick as the codec.
  connection->set_on_scene_update([this](const protocol::SceneUpdate& u) { on_scene_update(u); });
  connection->set_on_session_end([this, k](const client::ClientSession& s, const std::string&) { clients_[k].end_session(s); });
  SimClient& c = clients_[k];
  c.connection = connection;
  c.started_s = steady_now();
  c.traffic.sample(c.started_s, 0);
  connection->start();
}

codec::DecodeMemo* LoadShard::memo_for(const codec::StreamConfig& config) {
  for (const auto& memo : memos_)
    if (memo->config() == config) return memo.get();
  // Scene changes make new configurations; old memos stop being asked and stay small.
  return memos_.emplace_back(std::make_unique<codec::DecodeMemo>(config)).get();
}

// A frame shown by many clients (same shared_id) is compared with the truth once per thread.
FrameError LoadShard::checked_error(const codec::ReconstructedFrame& frame, Tick tick) {
  if (frame.shared_id != 0)
    if (const auto found = verdicts_.find(frame.shared_id); found != verdicts_.end()) return found->second;
  std::shared_ptr<const sim::Frame> truth;
  {
    std::lock_guard lock(shared_.truth_mutex);
    truth = shared_.truth->at(tick, facts_->grid);
  }
  ++truth_checks_;
  const FrameError error = frame_error(channels_of(frame), channels_of(*truth));  // every streamed channel
  if (frame.shared_id != 0) {
    verdicts_.emplace(frame.shared_id, error);
    while (verdicts_.size() > 4096) verdicts_.erase(verdicts_.begin());  // ids only grow: the oldest go
  }
  return error;
}

void LoadShard::on_welcome(std::size_t k, const protocol::Welcome& w) {
  bool first = false;
  {
    std::lock_guard lock(shared_.truth_mutex);
    if (!shared_.truth) {
      first = true;
      shared_.facts = StreamFacts::from(w);
      shared_.truth.emplace(shared_.facts->tick_rate_hz, shared_.facts->choppy, 256, w.stream.cascades);
      shared_.truth->set_scene(0, w.scene);
      shared_.truth->set_wake(w.stream.wake, w.vessels, w.scene);
    } else {
      shared_.truth->set_scene(w.current_tick, w.scene);
    }
    if (!facts_) {
      facts_ = *shared_.facts;
      truth_ = &*shared_.truth;
    }
  }
  if (first) warn_if_server_differs(w);
  SimClient& c = clients_[k];
  c.session_ended = false;  // a new session of this connection
  if (!c.welcome_tick) c.welcome_tick = w.current_tick;
  if (!c.tally) c.tally.emplace(facts_->tick_period_s, facts_->interval_ticks);
}

void LoadShard::on_scene_update(const protocol::SceneUpdate& u) {
  std::lock_guard lock(shared_.truth_mutex);
  if (!shared_.truth) return;
  shared_.truth->set_scene(u.effective_tick, u.scene);
  if (u.vessels) shared_.truth->set_vessels(*u.vessels, u.effective_tick);
}

void LoadShard::warn_if_server_differs(const protocol::Welcome& w) const {
  const Scenario* scenario = o_.scenario.empty() ? nullptr : find_scenario(o_.scenario);
  if (!scenario) return;
  if (const std::string why = server_mismatch(scenario->server, facts_->tick_rate_hz, w.epoch_unix_ms, unix_now_s(), w.vessels.size());
      !why.empty())
    std::fprintf(stderr, "ocean-loadtest: warning: the server does not run as scenario %s needs (%s): %s; "
                 "start it with client/loadtest/local_server.py\n", o_.scenario.c_str(), describe(scenario->server).c_str(), why.c_str());
}

Tick LoadShard::end_tick() const { return facts_->tick_at_unix(shared_.start_unix + o_.ramp_s + o_.duration_s - 1.0); }

void LoadShard::on_frame(std::size_t k, const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) {
  SimClient& c = clients_[k];
  if (!facts_ || !c.tally || measuring_done_) return;
  // The schedule owes frames up to one second before the end; later ones may still be in flight,
  // and count only as a client's first frame.
  const bool owed = tick <= end_tick();
  if (!owed && c.first_frame_s) return;
  const double now_unix = unix_now_s();
  const FrameError error = checked_error(frame, tick);
  const bool within_bound = within_bounds(error, facts_->bounds);
  if (within_bound && !c.first_frame_s) {
    c.first_frame_s = arrival_s;
    c.traffic.set_first_frame(arrival_s);
  }
  if (!owed) return;
  ClientTally& tally = *c.tally;
  tally.clock().observe(tick, arrival_s);
  FrameOutcome outcome;
  outcome.within_bound = within_bound;
  // The viewer's jitter buffer (FrameTimeline) adds delay on a jittery link and on a stream;
  // judge by the same.
  const client::ClientSession* session = c.live_session();
  const double delay = client::FrameTimeline::adaptive_delay(
      tally.clock(), facts_->interpolation_delay_s, static_cast<double>(facts_->interval_ticks) * facts_->tick_period_s,
      session ? session->stream_rtt_s() : 0.0);
  max_delay_s_ = std::max(max_delay_s_, delay);
  outcome.on_time = arrived_on_time(arrival_s, tick, *tally.clock().offset_s(), facts_->tick_period_s, delay);
  if (!tally.record(tick, outcome, error.height_m)) return;
  const double latency = now_unix - (facts_->epoch_s + truth_->time_of(tick));
  latency_all_.add(latency);
  latency_second_.add(latency);
  ++second_frames_;
  if (outcome.within_bound && outcome.on_time) ++second_ok_;
  if (!outcome.within_bound) ++second_bad_;
  if (k == 0 && recorder_) record(k, frame, tick);
}

void LoadShard::record(std::size_t, const codec::ReconstructedFrame& frame, Tick tick) {
  if (!record_error_.empty() || (recorded_tick_ && tick <= *recorded_tick_)) return;
  recorded_tick_ = tick;
  try {
    recorder_->append(tick, facts_->lattices, frame);
  } catch (const std::exception& e) {
    record_error_ = std::string("--record: ") + e.what();
  }
}

// Starts the clients due by now, and once a second reports this thread's share of the second.
void LoadShard::schedule_second(int second) {
  const double due = shared_.start_steady + second * 1.0;
  launch_due();
  arm_at(std::min(due, next_launch_time()), [this, second, due] {
    if (steady_now() + 1e-4 >= due) {
      second_tick(second);
      if (steady_now() < shared_.end_steady) schedule_second(second + 1);
      else finish();
    } else {
      schedule_second(second);
    }
  });
}

// Every 100 ms, each started client's received bytes, for its busiest second (ReceiveRate).
void LoadShard::schedule_sample(int n) {
  const double due = shared_.start_steady + n * kSampleS;
  const double wait = std::max(0.0, due - steady_now());
  sample_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wait)));
  sample_timer_.async_wait([this, n](const std::error_code& ec) {
    if (ec || measuring_done_) return;
    sample_traffic();
    // A loop that fell behind skips the samples it missed instead of bunching them.
    const int next = std::max(n + 1, static_cast<int>(std::floor((steady_now() - shared_.start_steady) / kSampleS)) + 1);
    schedule_sample(next);
  });
}

void LoadShard::sample_traffic() {
  const double now = steady_now();
  for (std::size_t k = 0; k < launched_; ++k) clients_[k].traffic.sample(now, clients_[k].bytes());
}

double LoadShard::next_launch_time() const {
  if (launched_ >= clients_.size()) return std::numeric_limits<double>::infinity();
  return shared_.start_steady + o_.ramp_s * static_cast<double>(global_index(launched_)) / static_cast<double>(o_.clients);
}

void LoadShard::launch_due() {
  while (launched_ < clients_.size() && next_launch_time() <= steady_now()) start_client(launched_++);
}

template <typename F>
void LoadShard::arm_at(double steady_s, F&& f) {
  const double wait = std::max(0.0, steady_s - steady_now());
  tick_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wait)));
  tick_timer_.async_wait([f = std::forward<F>(f)](const std::error_code& ec) {
    if (!ec) f();
  });
}

void LoadShard::second_tick(int second) {
  SecondPart part;
  part.second = second;
  std::uint64_t bytes = 0;
  for (const SimClient& c : clients_) {
    bytes += c.bytes();
    if (c.connection && c.connection->connected()) ++part.connected;
  }
  part.bytes = bytes - last_bytes_;
  part.frames = second_frames_;
  part.ok = second_ok_;
  part.bad = second_bad_;
  part.latency_s = latency_second_.sparse();
  shared_.board.add(part);
  last_bytes_ = bytes;
  second_frames_ = second_ok_ = second_bad_ = 0;
  latency_second_.clear();
}

void LoadShard::finish() {
  sample_traffic();
  measuring_done_ = true;
  sample_timer_.cancel();
  end_wall_steady_ = steady_now();
  for (const SimClient& c : clients_) {
    end_bytes_ += c.bytes();
    end_datagrams_ += c.udp_datagrams();
    if (c.connection && c.connection->connected()) ++connected_at_end_;
  }
  if (--shared_.unfinished == 0) {
    // The last thread to stop measuring: the run's CPU readings end here.
    std::lock_guard lock(shared_.stamp_mutex);
    shared_.end_steady_stamp = steady_now();
    shared_.cpu_end_s = own_cpu_s();
    shared_.server_cpu_end_s = process_cpu_s(o_.server_pid);
  }
  for (SimClient& c : clients_)
    if (c.connection) c.connection->stop();
  // Stop once the Byes are out (run() bounds this with run_for).
  arm_at(steady_now() + 0.2, [this] { io_.stop(); });
}

}  // namespace ocean::loadtest
