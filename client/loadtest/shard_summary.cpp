// LoadShard::summary: one thread's clients added up into a LoadSummary part.
#include "load_shard.hpp"

namespace ocean::loadtest {

void LoadShard::add_client_figures(LoadSummary& s, double wall) const {
  // A thread none of whose clients got a Welcome still owes the frames its clients never got.
  std::optional<StreamFacts> facts = facts_;
  if (!facts) {
    std::lock_guard lock(shared_.truth_mutex);
    facts = shared_.facts;
  }
  if (facts) {
    s.error_bound_m = facts->bounds.height_m;
    s.interpolation_delay_ms = facts->interpolation_delay_s * 1e3;
  }
  const Tick last_tick = facts ? facts->tick_at_unix(shared_.start_unix + o_.ramp_s + o_.duration_s - 1.0) : 0;
  for (std::size_t k = 0; k < clients_.size(); ++k) {
    const SimClient& c = clients_[k];
    s.connection.add(c.connection_facts());
    c.add_counters_to(s);
    const double started = o_.ramp_s * static_cast<double>(global_index(k)) / static_cast<double>(o_.clients);
    s.client_seconds += std::max(0.0, wall - started);
    if (!facts) continue;
    const Tick start_tick = c.welcome_tick.value_or(facts->tick_at_unix(shared_.start_unix + started));
    ClientTally empty(facts->tick_period_s, facts->interval_ticks);
    const ClientTally& t = c.tally ? *c.tally : empty;
    const std::uint64_t expected = t.expected(start_tick, last_tick);
    s.frames_expected += expected;
    if (c.welcome_tick) s.frames_expected_welcomed += expected;
    s.frames_received += t.received();
    s.frames_ok += t.ok();
    s.frames_late += t.late();
    s.frames_bad += t.bad();
    s.stalls += t.stalls();
    s.max_err_m = std::max(s.max_err_m, t.max_error_m());
    if (expected > t.received()) s.frames_lost += expected - t.received();
  }
}

LoadSummary LoadShard::summary() const {
  LoadSummary s;
  s.clients = static_cast<int>(clients_.size());
  s.clients_connected = connected_at_end_;
  s.profile = o_.profile;
  s.transport = o_.transport;
  s.link = o_.link_text;
  s.scenario = o_.scenario;
  s.bandwidth_bps = o_.bandwidth_bps;
  const double wall = end_wall_steady_ - shared_.start_steady;
  s.duration_s = wall;
  s.interpolation_delay_max_ms = max_delay_s_ * 1e3;
  add_client_figures(s, wall);
  s.latency_s = latency_all_.sparse();
  s.bytes_received = end_bytes_;
  s.udp_datagrams = end_datagrams_;
  s.truth_checks = truth_checks_;
  for (const auto& memo : memos_) {
    s.decodes_run += memo->counts().misses;
    s.decodes_shared += memo->counts().hits;
  }
  return s;
}

}  // namespace ocean::loadtest
