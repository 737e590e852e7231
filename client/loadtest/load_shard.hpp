// LoadShard: one thread's share of a load run - the clients i with i % threads == index, on its
// own io_context - each behind its own link models, every reconstructed frame checked against the
// shared GroundTruth. Its figures are a LoadSummary part that merges with the other threads'.
#pragma once

#include <asio/io_context.hpp>
#include <asio/steady_timer.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frame_recorder.hpp"
#include "frame_verdict.hpp"
#include "latency_histogram.hpp"
#include "load_summary.hpp"
#include "run_shared.hpp"
#include "sim_client.hpp"

namespace ocean::loadtest {

class LoadShard {
 public:
  LoadShard(RunShared& shared, int index, int count);

  // Runs the ramp and the measurement, then lets the Byes out; returns when done.
  void run();
  // This thread's part of the summary (not finalized; truth figures are the run's, not here).
  LoadSummary summary() const;
  const std::string& record_error() const { return record_error_; }
  // Why the first client's connection closed last ("" when it never did): for a run nobody joined.
  std::string first_close_reason() const;

 private:
  std::size_t global_index(std::size_t k) const { return static_cast<std::size_t>(index_) + k * static_cast<std::size_t>(count_); }
  void start_client(std::size_t k);
  codec::DecodeMemo* memo_for(const codec::StreamConfig& config);
  FrameError checked_error(const codec::ReconstructedFrame& frame, Tick tick);
  void on_welcome(std::size_t k, const protocol::Welcome& w);
  void on_scene_update(const protocol::SceneUpdate& u);
  void warn_if_server_differs(const protocol::Welcome& w) const;
  Tick end_tick() const;
  void on_frame(std::size_t k, const codec::ReconstructedFrame& frame, Tick tick, double arrival_s);
  void record(std::size_t k, const codec::ReconstructedFrame& frame, Tick tick);
  void schedule_second(int second);
  void schedule_sample(int n);
  void sample_traffic();
  double next_launch_time() const;
  void launch_due();
  template <typename F>
  void arm_at(double steady_s, F&& f);
  void second_tick(int second);
  void finish();
  void add_client_figures(LoadSummary& s, double wall) const;

  RunShared& shared_;
  const LoadtestOptions& o_;
  int index_, count_;
  asio::io_context io_;
  std::vector<SimClient> clients_;
  asio::steady_timer tick_timer_, sample_timer_;
  static constexpr double kSampleS = 0.1;
  std::size_t launched_ = 0;
  std::optional<StreamFacts> facts_;  // a copy of the run's, once this thread has seen a Welcome
  GroundTruth* truth_ = nullptr;      // the run's (RunShared::truth); only time_of without the lock
  LatencyHistogram latency_all_, latency_second_;
  std::uint64_t second_frames_ = 0, second_ok_ = 0, second_bad_ = 0, last_bytes_ = 0;
  double end_wall_steady_ = 0.0;
  bool measuring_done_ = false;
  double max_delay_s_ = 0.0;  // the largest jitter-adapted delay any client's frame was judged by
  int connected_at_end_ = 0;
  std::uint64_t end_bytes_ = 0, end_datagrams_ = 0;
  std::string record_error_;
  std::optional<client::FrameRecorder> recorder_;  // client 0's, on the thread that holds it
  std::optional<Tick> recorded_tick_;              // client 0's file holds frames in tick order
  std::vector<std::unique_ptr<codec::DecodeMemo>> memos_;
  std::map<std::uint64_t, FrameError> verdicts_;  // by ReconstructedFrame::shared_id
  std::uint64_t truth_checks_ = 0;
};

}  // namespace ocean::loadtest
