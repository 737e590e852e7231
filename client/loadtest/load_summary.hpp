// LoadSummary: the figures of one load-test run, printed as a human table or one JSON object. The
// JSON carries the parts (histograms, byte counts) the figures are computed from, so summaries of
// several threads or processes merge into one (summary_merge.hpp) with exact percentiles.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>

#include "client_figures.hpp"
#include "sparse_histogram.hpp"

namespace ocean::loadtest {

// The connection figures (time to first frame, 1 s peaks, calm rate) are ConnectionFigures, computed
// over all clients by connection_figures(); the rest is summed here.
struct LoadSummary : ConnectionFigures {
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
  // Clients not connected at the end whose last attempt the server refused (an Error before the
  // Welcome), by the Error's reason: what admission control said to the clients beyond capacity.
  std::map<std::string, std::uint64_t> refusals;
  // Clients that never got a Welcome, by how their last attempt ended: "refused: <reason>" (the
  // server said why), "connecting" (still trying), or the client's own close reason (no Welcome
  // in time, connection refused...). Beyond capacity it shows whether every client turned away
  // was told why.
  std::map<std::string, std::uint64_t> not_welcomed;
  // Frames owed to the clients that got a Welcome: beyond capacity, the refused clients' frames
  // are all lost, and the admitted clients' service is judged over these alone.
  std::uint64_t frames_expected_welcomed = 0;
  double frames_ok_pct = 0.0;    // verified and on time, over frames expected
  double frames_ok_pct_welcomed = 0.0;  // verified and on time, over frames_expected_welcomed
  double max_err_m = 0.0;
  double error_bound_m = 0.0;
  double kbps_mean = 0.0;        // received kbit/s per client, envelopes included
  double kbps_mean_ip = 0.0;     // kbps_mean plus 28 bytes of IPv4/UDP header per datagram received
  double latency_p50_ms = 0.0, latency_p99_ms = 0.0, latency_max_ms = 0.0;
  double interpolation_delay_ms = 0.0;      // the base: three send intervals
  double interpolation_delay_max_ms = 0.0;  // the most any client's jitter buffer added up to
  std::optional<double> server_cpu_pct;
  double loadtest_cpu_pct = 0.0;
  double duration_s = 0.0;
  std::string profile, transport, link, scenario;
  std::uint64_t bandwidth_bps = 0;  // announced in every client's Hello (0 = unstated)
  int threads = 1;    // threads the clients ran on, over all processes merged
  int processes = 1;  // load-test processes merged into this summary

  // What the non-additive figures are computed from (finalize): latencies of every counted frame
  // (0.1 ms bins), the per-client connection facts, and the traffic behind kbps_mean.
  SparseHistogram latency_s{1e-4};
  ConnectionParts connection;
  std::uint64_t bytes_received = 0, udp_datagrams = 0;
  double client_seconds = 0.0;  // over clients: the time each was part of the run
};

// Fills in frames_ok_pct, kbps_mean(_ip), the latency percentiles and the ConnectionFigures from
// the counts and parts above.
void finalize(LoadSummary& s);

void print_table(std::ostream& out, const LoadSummary& s);
std::string to_json(const LoadSummary& s);  // one line, no trailing newline

}  // namespace ocean::loadtest
