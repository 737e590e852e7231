// LoadSummary: the figures of one load-test run, printed as a human table or one JSON object.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>

namespace ocean::loadtest {

struct LoadSummary {
  int clients = 0;
  int clients_connected = 0;     // connected at the end
  int clients_welcomed = 0;      // got a Welcome at least once during the run
  int scenes = 0;                // distinct scenes the frames were checked against (1 + weather changes seen)
  std::uint64_t frames_expected = 0, frames_received = 0, frames_ok = 0, frames_late = 0, frames_lost = 0,
                frames_bad = 0, stalls = 0, keyframes = 0, reconnects = 0, truth_evaluations = 0;
  // Decodes the clients ran and frames checked against the truth; with a shared DecodeMemo, a
  // frame several clients decoded identically is decoded and checked once.
  std::uint64_t decodes_run = 0, decodes_shared = 0, truth_checks = 0;
  // Client-side explanations of lost frames, summed over every session.
  std::uint64_t chunks_rejected_by_codec = 0, messages_rejected = 0, keyframe_requests = 0, transport_fallbacks = 0;
  std::uint64_t frames_recovered = 0;  // completed from a FrameBundle copy after their own datagram was lost
  std::map<std::string, std::uint64_t> codec_rejections;  // by codec::ChunkError name
  double frames_ok_pct = 0.0;    // verified and on time, over frames expected
  double max_err_m = 0.0;
  double error_bound_m = 0.0;
  double kbps_mean = 0.0;        // received kbit/s per client, envelopes included
  double kbps_mean_ip = 0.0;     // kbps_mean plus 28 bytes of IPv4/UDP header per datagram received
  // Busiest 1 s a client received (bytes as kbps_mean): the largest and the median client's, from
  // each client's first frame on, and the largest of the windows before it (the connection's start).
  double kbps_peak_1s = 0.0, kbps_peak_1s_p50 = 0.0, kbps_peak_1s_startup = 0.0;
  // The median client's median 100 ms rate from its first frame on: the stream between bursts.
  double kbps_calm = 0.0;
  // Time to first frame: a client's first connection attempt to its first complete frame within
  // the error bound; over the clients that got one (none: no client did).
  std::optional<double> ttff_max_s, ttff_p50_s;
  int clients_without_frame = 0;
  double latency_p50_ms = 0.0, latency_p99_ms = 0.0, latency_max_ms = 0.0;
  double interpolation_delay_ms = 0.0;      // the base: three send intervals
  double interpolation_delay_max_ms = 0.0;  // the most any client's jitter buffer added up to
  std::optional<double> server_cpu_pct;
  double loadtest_cpu_pct = 0.0;
  double duration_s = 0.0;
  std::string profile, transport, link, scenario;
  std::uint64_t bandwidth_bps = 0;  // announced in every client's Hello (0 = unstated)
};

void print_table(std::ostream& out, const LoadSummary& s);
std::string to_json(const LoadSummary& s);  // one line, no trailing newline

}  // namespace ocean::loadtest
