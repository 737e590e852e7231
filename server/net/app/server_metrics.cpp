#include "server_metrics.hpp"

#include "log_sink.hpp"

#include "chunk_format.hpp"
#include "protocol_version.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>

namespace ocean::server {

ServerMetrics::ServerMetrics(MetricsRegistry& registry)
    : ticks(registry.counter("ocean_ticks_total", "Simulation ticks run.")),
      ticks_late(registry.counter("ocean_ticks_late_total",
                                  "Ticks run after the following tick was already due (the loop fell behind).")),
      ticks_skipped(registry.counter("ocean_ticks_skipped_total",
                                     "Ticks never run because the loop was too far behind (catch-up policy).")),
      tick_seconds(registry.summary("ocean_tick_seconds", "Simulation time per tick for all offered profiles.")),
      frames_dropped(registry.counter("ocean_frames_dropped_total",
                                      "Computed tick frames dropped because the network side was behind.")),
      current_tick(registry.gauge("ocean_tick", "Index of the last tick run, counted from the epoch.")),
      scene_changes(registry.counter("ocean_scene_changes_total", "Scene changes applied (schedule or admin ParamChange).")),
      keyframes_sent(registry.counter("ocean_keyframes_sent_total", "Keyframes queued to clients.")),
      key_bytes_sent(registry.counter("ocean_key_bytes_sent_total",
                                      "Bytes of the keyframes queued to clients, which the server-wide key budget paces.")),
      encodes(registry.counter("ocean_encodes_total", "Encoder runs (one per profile, tick and baseline).")),
      encodes_last_tick(registry.gauge("ocean_encodes_last_tick",
                                       "Encoder runs for the last tick over all profiles; clients sharing a baseline share one.")),
      send_queue_drops(registry.counter("ocean_send_queue_drops_total",
                                        "Frames not queued because a client's bounded send queue was full.")),
      frames_skipped_bandwidth(registry.counter("ocean_frames_skipped_bandwidth_total",
                                                "Frames skipped to stay within a client's announced bandwidth.")),
      param_changes(registry.counter("ocean_param_changes_total", "Admin parameter changes accepted.")),
      height_queries(registry.counter("ocean_height_queries_total", "Admin HeightQueries answered.")),
      send_queue_max_bytes(registry.gauge("ocean_send_queue_max_bytes",
                                          "Largest TCP send queue of any client at the last tick, bytes (bounded).")),
      bundled_copies(registry.counter("ocean_udp_bundled_copies_total",
                                      "Earlier unacknowledged frames copied into UDP datagrams (FrameBundle).")),
      root_merges(registry.counter("ocean_key_root_merges_total",
                                   "Key roots whose sessions were keyed again to keep a profile within its root cap.")),
      keys_deferred_roots(registry.counter("ocean_keys_deferred_roots_total",
                                           "Key ticks a session needing a key waited because its profile's key roots "
                                           "filled the cap (until one is old enough to merge).")),
      sessions_started(registry.counter("ocean_sessions_started_total", "Client sessions welcomed.")),
      udp_send_drops(registry.counter("ocean_udp_send_drops_total",
                                      "Datagrams the kernel refused to send (full socket buffer, unreachable peer).")),
      frames_skipped_load(registry.counter("ocean_frames_skipped_load_total",
                                           "Frames or keys sessions waited for because a load budget (keys/s, encodes/tick) ran out.")),
      frames_rebased_load(registry.counter("ocean_frames_rebased_load_total",
                                           "Frames predicted from an older acked state that was already encoded, because the "
                                           "encode budget per tick ran out.")),
      serve_seconds(registry.summary("ocean_serve_seconds", "Network-thread time to serve one tick (encodes and sends).")),
      loop_lag_seconds(registry.summary("ocean_loop_lag_seconds", "How long after its scheduled time each tick was served.")),
      network_busy_ratio(registry.gauge("ocean_network_busy_ratio",
                                        "Share of the last second the network thread was busy: running, or ready to run "
                                        "and waiting for a CPU.")),
      network_cpu_wait_ratio(registry.gauge("ocean_network_cpu_wait_ratio",
                                            "Share of the last second the network thread was ready to run but waited for a "
                                            "CPU (something else busy on its core).")),
      admission_capacity(registry.gauge("ocean_admission_capacity",
                                        "Sessions the network thread is projected to serve at its target load; a Hello "
                                        "beyond it is refused as server_full (0 = no limit).")),
      udp_unproven_bytes_in(registry.counter("ocean_udp_unproven_bytes_total",
                                             "UDP bytes from and to addresses not proven by a UdpHello.",
                                             {{"direction", "in"}})),
      udp_unproven_bytes_out(registry.counter("ocean_udp_unproven_bytes_total",
                                              "UDP bytes from and to addresses not proven by a UdpHello.",
                                              {{"direction", "out"}})),
      udp_rebinds(registry.counter("ocean_udp_rebinds_total",
                                   "Proven UDP addresses moved to a new port after the old one went quiet.")),
      udp_rebinds_refused(registry.counter("ocean_udp_rebinds_refused_total",
                                           "UdpHellos refused because they would move a live proven address.")),
      udp_rebinds_reclaimed(registry.counter("ocean_udp_rebinds_reclaimed_total",
                                             "UDP moves undone because the address moved away from spoke again.")),
      sighups(registry.counter("ocean_sighups_total",
                               "SIGHUPs received: the TLS certificate (--tls-cert) is read again, nothing else; still serving.")),
      tls_reload_failures(registry.counter("ocean_tls_reload_failures_total",
                                           "SIGHUPs whose --tls-cert or --tls-key could not be read: the old pair stays in force.")),
      log_write_failures(registry.counter("ocean_log_write_failures_total",
                                          "Log lines that could not be written (the log's reader gone, a full disk).")),
      timeline_entries(registry.counter("ocean_timeline_entries_total", "Entries of the fleet's timeline applied.")),
      timeline_late_entries(registry.counter(
          "ocean_timeline_late_entries_total",
          "Entries of the fleet's timeline decided after their tick here (held until then, then every viewer keyed again).")),
      timeline_refused(registry.counter("ocean_timeline_refused_total",
                                        "Timeline entries not taken: refused or unconfirmed by the store (on the replica that "
                                        "took them), or aborted by the fleet (on every replica).")),
      timeline_held_ticks(registry.counter("ocean_timeline_held_ticks_total",
                                           "Ticks this server streamed no frame: a timeline entry undecided at its tick, or "
                                           "its lease on the store in doubt.")),
      timeline_skipped(registry.counter("ocean_timeline_skipped_total",
                                        "Entries of the fleet's timeline skipped by every replica (unreadable, or out of range).")),
      timeline_index(registry.gauge("ocean_timeline_index", "Entries of the fleet's timeline read so far.")),
      timeline_age_seconds(registry.gauge("ocean_timeline_age_seconds",
                                          "Seconds since the timeline's store last answered a read (-1: never).")),
      registry_(registry),
      resident_bytes_(registry.gauge("process_resident_memory_bytes", "Resident memory of the server process, bytes.")),
      cpu_seconds_(registry.gauge("process_cpu_seconds_total", "User and system CPU time of the server process, seconds.")),
      open_fds_(registry.gauge("process_open_fds", "Open file descriptors of the server process.")),
      start_time_(registry.gauge("process_start_time_seconds", "Start time of the server process, Unix seconds.")) {
  registry.gauge("ocean_build_info", "Always 1; the labels name the build.",
                 {{"version", OCEAN_VERSION},
                  {"protocol", std::to_string(protocol::kProtocolVersion)},
                  {"codec", std::to_string(codec::kCodecVersion)}})
      .set(1.0);
  start_time_.set(static_cast<double>(std::time(nullptr)));
}

Summary& ServerMetrics::encode_seconds(std::string_view profile) {
  return registry_.summary("ocean_encode_seconds", "Encoder time of a profile's stream in a tick that encoded.",
                           {{"profile", std::string(profile)}});
}

void ServerMetrics::update_process() {
  log_write_failures.inc(static_cast<double>(LogSink::failed_writes()) - log_write_failures.value());
  // /proc/self/stat fields 14 and 15 (utime, stime) in clock ticks; statm's second field in pages.
  if (std::FILE* stat = std::fopen("/proc/self/stat", "r")) {
    char buffer[1024] = {};
    const std::size_t n = std::fread(buffer, 1, sizeof buffer - 1, stat);
    std::fclose(stat);
    const char* after_name = std::strrchr(buffer, ')');  // the command name may hold spaces
    unsigned long utime = 0, stime = 0;
    if (n > 0 && after_name &&
        std::sscanf(after_name + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &utime, &stime) == 2)
      cpu_seconds_.set(static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK)));
  }
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    unsigned long pages = 0, resident = 0;
    if (std::fscanf(statm, "%lu %lu", &pages, &resident) == 2)
      resident_bytes_.set(static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)));
    std::fclose(statm);
  }
  std::error_code error;
  std::size_t fds = 0;
  for (auto it = std::filesystem::directory_iterator("/proc/self/fd", error); !error && it != std::filesystem::directory_iterator();
       it.increment(error))
    ++fds;
  if (!error) open_fds_.set(static_cast<double>(fds));
}

Counter& ServerMetrics::frames_computed(std::string_view profile) {
  return registry_.counter("ocean_frames_computed_total", "Frames computed by the simulation, by profile.",
                           {{"profile", std::string(profile)}});
}

Gauge& ServerMetrics::clients(std::string_view profile, std::string_view transport) {
  return registry_.gauge("ocean_clients", "Connected clients by profile and transport.",
                         {{"profile", std::string(profile)}, {"transport", std::string(transport)}});
}

namespace {

template <typename Make>
Counter& remembered(std::vector<std::pair<std::string, Counter*>>& seen, std::string_view label, Make make) {
  for (const auto& [name, counter] : seen)
    if (name == label) return *counter;
  Counter& counter = make();
  seen.emplace_back(std::string(label), &counter);
  return counter;
}

}  // namespace

Counter& ServerMetrics::frames_sent(std::string_view transport) {
  return remembered(frames_sent_, transport, [&]() -> Counter& {
    return registry_.counter("ocean_frames_sent_total", "Frames sent to clients, by transport.",
                             {{"transport", std::string(transport)}});
  });
}

Counter& ServerMetrics::bytes_sent(std::string_view transport) {
  return remembered(bytes_sent_, transport, [&]() -> Counter& {
    return registry_.counter("ocean_bytes_sent_total", "Payload bytes sent to clients, by transport.",
                             {{"transport", std::string(transport)}});
  });
}

Counter& ServerMetrics::rejects(std::string_view reason) {
  return registry_.counter("ocean_rejects_total", "Connections and packets refused, by reason.",
                           {{"reason", std::string(reason)}});
}

Counter& ServerMetrics::sessions_ended(std::string_view reason) {
  return registry_.counter("ocean_sessions_ended_total",
                           "Welcomed client sessions that closed, by reason (client_bye, peer_closed, idle_timeout...).",
                           {{"reason", std::string(reason)}});
}

Counter& ServerMetrics::samples_saturated(std::string_view profile) {
  return registry_.counter("ocean_samples_saturated_total",
                           "Frame values a stream clamped to its 2^20 quantization steps (its viewers see them flattened).",
                           {{"profile", std::string(profile)}});
}

Counter& ServerMetrics::log_suppressed(std::string_view reason) {
  return registry_.counter("ocean_log_suppressed_total",
                           "Log lines left out by the per-reason and per-peer rate limit (the events are counted elsewhere).",
                           {{"reason", std::string(reason)}});
}

}  // namespace ocean::server
