#include "load_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/json_writer.hpp"
#include "summary_fields.hpp"

namespace ocean::loadtest {
namespace {

constexpr int kIpUdpHeaderBytes = 28;  // IPv4 20 + UDP 8, per datagram

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// {"bin":W,"max":M,"bins":[[index,count],...]}: the max with 17 digits, so that a percentile read
// back (capped at the max) is the one written.
std::string histogram_json(const SparseHistogram& h) {
  std::string bins = "[";
  for (const auto& [bin, n] : h.bins()) {
    if (bins.size() > 1) bins += ',';
    bins += '[';
    bins += std::to_string(bin);
    bins += ',';
    bins += std::to_string(n);
    bins += ']';
  }
  common::JsonWriter w(common::JsonWriter::Style::compact);
  w.number("bin", h.bin_width(), 17).number("max", h.max(), 17).raw("bins", bins + "]");
  return w.str();
}

std::string parts_json(const LoadSummary& s) {
  common::JsonWriter w(common::JsonWriter::Style::compact);
  w.raw("latency_s", histogram_json(s.latency_s))
      .raw("ttff_s", histogram_json(s.connection.ttff_s))
      .raw("peak_kbps", histogram_json(s.connection.peak_kbps))
      .raw("calm_kbps", histogram_json(s.connection.calm_kbps))
      .number("startup_peak_kbps", s.connection.startup_peak_kbps, 17)
      .integer("clients_without_frame", s.connection.clients_without_frame)
      .integer("bytes_received", s.bytes_received)
      .integer("udp_datagrams", s.udp_datagrams)
      .number("client_seconds", s.client_seconds, 17);
  return w.str();
}

std::string optional_json(const std::optional<double>& v) { return v ? num(*v) : "null"; }

}  // namespace

void finalize(LoadSummary& s) {
  s.frames_ok_pct = s.frames_expected ? 100.0 * static_cast<double>(std::min(s.frames_ok, s.frames_expected)) / static_cast<double>(s.frames_expected) : 0.0;
  s.frames_ok_pct_welcomed = s.frames_expected_welcomed ? 100.0 * static_cast<double>(std::min(s.frames_ok, s.frames_expected_welcomed)) / static_cast<double>(s.frames_expected_welcomed) : 0.0;
  const double per_client_s = s.client_seconds > 0 ? 8.0 / 1000.0 / s.client_seconds : 0.0;
  s.kbps_mean = static_cast<double>(s.bytes_received) * per_client_s;
  s.kbps_mean_ip = static_cast<double>(s.bytes_received + kIpUdpHeaderBytes * s.udp_datagrams) * per_client_s;
  s.latency_p50_ms = s.latency_s.percentile(50) * 1e3;
  s.latency_p99_ms = s.latency_s.percentile(99) * 1e3;
  s.latency_max_ms = s.latency_s.max() * 1e3;
  static_cast<ConnectionFigures&>(s) = s.connection.figures();
}

std::string to_json(const LoadSummary& s) {
  common::JsonWriter w(common::JsonWriter::Style::compact);
  for (const auto& f : kSummedInts) w.integer(f.name, s.*f.member);
  w.raw("frames_ok_pct", num(s.frames_ok_pct)).raw("frames_ok_pct_welcomed", num(s.frames_ok_pct_welcomed));
  for (const auto& f : kSummedCounts) w.integer(f.name, s.*f.member);
  for (const auto& f : kLargestDoubles) w.raw(f.name, num(s.*f.member));
  for (const auto& f : kSameDoubles) w.raw(f.name, num(s.*f.member));
  w.raw("kbps_mean", num(s.kbps_mean)).raw("kbps_mean_ip", num(s.kbps_mean_ip));
  w.raw("kbps_peak_1s", num(s.kbps_peak_1s)).raw("kbps_peak_1s_p50", num(s.kbps_peak_1s_p50));
  w.raw("kbps_peak_1s_startup", num(s.kbps_peak_1s_startup)).raw("kbps_calm", num(s.kbps_calm));
  w.raw("ttff_max_s", optional_json(s.ttff_max_s)).raw("ttff_p50_s", optional_json(s.ttff_p50_s));
  w.integer("clients_without_frame", s.clients_without_frame);
  w.raw("latency_p50_ms", num(s.latency_p50_ms)).raw("latency_p99_ms", num(s.latency_p99_ms));
  w.raw("latency_max_ms", num(s.latency_max_ms));
  if (s.server_cpu_pct) w.raw("server_cpu_pct", num(*s.server_cpu_pct));
  for (const auto& f : kSummedDoubles) w.raw(f.name, num(s.*f.member));
  w.integer("scenes", s.scenes);
  for (const auto& f : kSummedMaps) {
    common::JsonWriter counts(common::JsonWriter::Style::compact);
    for (const auto& [name, n] : s.*f.member) counts.integer(name, n);
    w.raw(f.name, counts.str());
  }
  for (const auto& f : kSameTexts) w.text(f.name, s.*f.member);
  w.integer("bandwidth_bps", s.bandwidth_bps);
  w.raw("parts", parts_json(s));
  return w.str();
}

void print_table(std::ostream& out, const LoadSummary& s) {
  char line[160];
  auto row = [&](const char* name, const std::string& value) {
    std::snprintf(line, sizeof line, "  %-24s %s\n", name, value.c_str());
    out << line;
  };
  out << "ocean-loadtest summary\n";
  row("scenario", s.scenario.empty() ? "(none)" : s.scenario);
  row("profile / transport", s.profile + " / " + s.transport);
  row("link", s.link.empty() ? "(no impairment)" : s.link);
  row("announced bandwidth", s.bandwidth_bps ? num(s.bandwidth_bps / 1e3) + " kbit/s" : "(unstated)");
  row("clients (connected)", std::to_string(s.clients) + " (" + std::to_string(s.clients_connected) + " at the end, " +
                                  std::to_string(s.clients_welcomed) + " ever)");
  row("duration s", num(s.duration_s));
  row("frames expected", std::to_string(s.frames_expected));
  row("frames ok (on time) %", num(s.frames_ok_pct) + " (of clients welcomed: " + num(s.frames_ok_pct_welcomed) + ")");
  row("frames late", std::to_string(s.frames_late));
  row("frames lost", std::to_string(s.frames_lost));
  row("frames bad", std::to_string(s.frames_bad));
  row("max error m (bound)", num(s.max_err_m) + " (" + num(s.error_bound_m) + ")");
  row("stalls", std::to_string(s.stalls));
  row("keyframes", std::to_string(s.keyframes));
  row("scenes checked", std::to_string(s.scenes));
  row("reconnects", std::to_string(s.reconnects));
  row("keyframe requests", std::to_string(s.keyframe_requests));
  row("chunks rejected (codec)", std::to_string(s.chunks_rejected_by_codec));
  for (const auto& [name, n] : s.codec_rejections) {
    std::string label = "  codec: ";
    label += name;
    row(label.c_str(), std::to_string(n));
  }
  for (const auto& [reason, n] : s.refusals) row(("refused: " + reason).c_str(), std::to_string(n));
  for (const auto& [why, n] : s.not_welcomed) row(("never welcomed: " + why).c_str(), std::to_string(n));
  row("messages rejected", std::to_string(s.messages_rejected));
  row("fallbacks to tcp", std::to_string(s.transport_fallbacks));
  row("frames recovered", std::to_string(s.frames_recovered));
  row("decodes run / shared", std::to_string(s.decodes_run) + " / " + std::to_string(s.decodes_shared));
  row("kbit/s per client", num(s.kbps_mean) + " (with IP/UDP headers " + num(s.kbps_mean_ip) + ")");
  row("peak 1 s kbit/s max/p50", num(s.kbps_peak_1s) + " / " + num(s.kbps_peak_1s_p50) + " (from the first frame on)");
  row("peak 1 s kbit/s startup", num(s.kbps_peak_1s_startup) + " (windows before the first frame)");
  row("calm kbit/s", num(s.kbps_calm) + " (median 1 s window after the first frame)");
  auto seconds = [](const std::optional<double>& v) { return v ? num(*v) : std::string("none"); };
  row("first frame s max/p50", seconds(s.ttff_max_s) + " / " + seconds(s.ttff_p50_s));
  row("clients without frame", std::to_string(s.clients_without_frame));
  row("latency p50/p99/max ms", num(s.latency_p50_ms) + " / " + num(s.latency_p99_ms) + " / " + num(s.latency_max_ms));
  row("interpolation delay ms", num(s.interpolation_delay_ms));
  row("interpolation delay max ms", num(s.interpolation_delay_max_ms));
  row("server cpu %", s.server_cpu_pct ? num(*s.server_cpu_pct) : "(unknown: pass --server-pid)");
  row("loadtest cpu %", num(s.loadtest_cpu_pct) + " (" + std::to_string(s.threads) + " threads, " + std::to_string(s.processes) + " process" + (s.processes == 1 ? ")" : "es)"));
}

}  // namespace ocean::loadtest
