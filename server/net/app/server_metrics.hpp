// ServerMetrics: the metrics ocean-server exports, by name, so call sites record without string
// lookups on hot paths. Per-label series (profile, transport, reason) are created on first use.
#pragma once

#include "metrics.hpp"

#include <string_view>
#include <utility>
#include <vector>

namespace ocean::server {

class ServerMetrics {
 public:
  explicit ServerMetrics(MetricsRegistry& registry);

  MetricsRegistry& registry() { return registry_; }

  Counter& ticks;            // ticks run
  Counter& ticks_late;       // ticks run after the following tick was already due
  Counter& ticks_skipped;    // ticks never run (catch-up policy jumped over them)
  Summary& tick_seconds;     // simulation time per tick, all profiles
  Counter& frames_dropped;   // computed frames the network side had no room for
  Gauge& current_tick;       // the last tick index run
  Counter& scene_changes;    // scheduled scene changes applied
  Counter& keyframes_sent;   // keyframes queued to clients
  Counter& key_bytes_sent;   // their bytes: what the key budget (key_bytes_per_s) paces
  Counter& encodes;          // encoder runs (each a distinct profile, tick and baseline)
  Gauge& encodes_last_tick;  // encoder runs for the last tick, all profiles: the sharing proof
  Counter& send_queue_drops; // frames not queued because a client's send queue was full
  Counter& frames_skipped_bandwidth;  // frames skipped to stay within a client's bandwidth_bps
  Counter& param_changes;    // admin ParamChanges accepted
  Counter& height_queries;   // admin HeightQueries answered
  Gauge& send_queue_max_bytes;   // max over sessions of queued TCP bytes, per tick
  Counter& bundled_copies;   // earlier frames re-sent inside FrameBundles
  Counter& root_merges;      // key roots merged into a newer key (beyond the profile's root cap)
  Counter& keys_deferred_roots;  // key ticks a joiner waited because its profile's roots filled the cap
  Counter& sessions_started; // Welcomes sent
  Counter& udp_send_drops;   // datagrams the kernel refused (full socket buffer, unreachable peer)
  Counter& frames_skipped_load;  // frames or keys a session waited for because a load budget ran out
  Counter& frames_rebased_load;  // frames that took an existing encode instead when the budget ran out
  Summary& serve_seconds;    // network-thread time to serve one tick (encodes, sends)
  Summary& loop_lag_seconds; // how long after its scheduled time a tick was served
  Gauge& network_busy_ratio; // share of the last second the network thread was busy (running or waiting for a CPU)
  Gauge& network_cpu_wait_ratio;  // share of the last second it waited for a CPU (another busy thread or process on its core)
  Gauge& admission_capacity; // the sessions the network thread is projected to serve at its target load (0 = no limit)
  Counter& udp_unproven_bytes_in;   // UDP bytes from addresses not (yet) proven (anti-amplification)
  Counter& udp_unproven_bytes_out;  // UDP bytes answered to them
  Counter& udp_rebinds;             // proven UDP addresses moved to a new port (NAT rebinding)
  Counter& udp_rebinds_refused;     // UdpHellos that would move a live proven address (replays)
  Counter& udp_rebinds_reclaimed;   // moves undone because the old address spoke again
  Counter& sighups;                 // SIGHUPs received (the TLS certificate is read again; nothing else)
  Counter& tls_reload_failures;     // SIGHUPs whose certificate could not be read (the old one stays)
  Counter& log_write_failures;      // log lines that could not be written (a reader gone, a full disk)
  // The fleet's timeline (--timeline): entries applied, entries read after their tick, this
  // replica's appends the store refused or never confirmed, entries skipped; entries read, and seconds since the
  // store last answered a read (-1 before the first).
  Counter& timeline_entries;
  Counter& timeline_late_entries;
  Counter& timeline_refused;
  Counter& timeline_held_ticks;  // ticks this replica served no frame: undecided entry, or lease in doubt
  Counter& timeline_skipped;  // entries every replica skips: unreadable, or a scene no profile can carry
  Gauge& timeline_index;
  Gauge& timeline_age_seconds;

  Counter& frames_computed(std::string_view profile);
  Summary& encode_seconds(std::string_view profile);  // encoder time of that profile in a tick that encoded
  Gauge& clients(std::string_view profile, std::string_view transport);
  Counter& frames_sent(std::string_view transport);
  Counter& bytes_sent(std::string_view transport);
  Counter& rejects(std::string_view reason);
  // process_* (memory, CPU, descriptors, start time) read from /proc now: call before rendering.
  void update_process();
  Counter& sessions_ended(std::string_view reason);  // welcomed sessions closed, by the link's reason
  Counter& log_suppressed(std::string_view reason);      // log lines left out by the rate limit (server_log.hpp)
  Counter& samples_saturated(std::string_view profile);  // values a stream clamped to its 2^20 steps

 private:
  MetricsRegistry& registry_;
  Gauge& resident_bytes_;
  Gauge& cpu_seconds_;
  Gauge& open_fds_;
  Gauge& start_time_;
  // Sending looks these up for every frame: a registry lookup each time was 1 % of the server.
  std::vector<std::pair<std::string, Counter*>> frames_sent_, bytes_sent_;
};

}  // namespace ocean::server
