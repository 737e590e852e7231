#include "load_summary.hpp"

#include <cmath>
#include <cstdio>

namespace ocean::loadtest {
namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::string to_json(const LoadSummary& s) {
  std::string j = "{";
  auto field = [&](const char* name, const std::string& value) {
    if (j.size() > 1) j += ",";
    j += "\"";
    j += name;
    j += "\":" + value;
  };
  auto u = [](std::uint64_t v) { return std::to_string(v); };
  field("clients", std::to_string(s.clients));
  field("clients_connected", std::to_string(s.clients_connected));
  field("clients_welcomed", std::to_string(s.clients_welcomed));
  field("frames_ok_pct", num(s.frames_ok_pct));
  field("frames_bad", u(s.frames_bad));
  field("max_err_m", num(s.max_err_m));
  field("error_bound_m", num(s.error_bound_m));
  field("kbps_mean", num(s.kbps_mean));
  field("kbps_mean_ip", num(s.kbps_mean_ip));
  field("kbps_peak_1s", num(s.kbps_peak_1s));
  field("kbps_peak_1s_p50", num(s.kbps_peak_1s_p50));
  field("kbps_peak_1s_startup", num(s.kbps_peak_1s_startup));
  field("kbps_calm", num(s.kbps_calm));
  field("ttff_max_s", s.ttff_max_s ? num(*s.ttff_max_s) : "null");
  field("ttff_p50_s", s.ttff_p50_s ? num(*s.ttff_p50_s) : "null");
  field("clients_without_frame", std::to_string(s.clients_without_frame));
  field("latency_p50_ms", num(s.latency_p50_ms));
  field("latency_p99_ms", num(s.latency_p99_ms));
  field("latency_max_ms", num(s.latency_max_ms));
  if (s.server_cpu_pct) field("server_cpu_pct", num(*s.server_cpu_pct));
  field("loadtest_cpu_pct", num(s.loadtest_cpu_pct));
  field("frames_expected", u(s.frames_expected));
  field("frames_received", u(s.frames_received));
  field("frames_ok", u(s.frames_ok));
  field("frames_late", u(s.frames_late));
  field("frames_lost", u(s.frames_lost));
  field("stalls", u(s.stalls));
  field("keyframes", u(s.keyframes));
  field("reconnects", u(s.reconnects));
  field("truth_evaluations", u(s.truth_evaluations));
  field("scenes", std::to_string(s.scenes));
  field("decodes_run", u(s.decodes_run));
  field("decodes_shared", u(s.decodes_shared));
  field("truth_checks", u(s.truth_checks));
  field("keyframe_requests", u(s.keyframe_requests));
  field("chunks_rejected_by_codec", u(s.chunks_rejected_by_codec));
  std::string reasons = "{";
  for (const auto& [name, n] : s.codec_rejections) {
    if (reasons.size() > 1) reasons += ',';
    reasons += json_string(name);
    reasons += ':';
    reasons += u(n);
  }
  field("codec_rejections", reasons + "}");
  field("messages_rejected", u(s.messages_rejected));
  field("transport_fallbacks", u(s.transport_fallbacks));
  field("frames_recovered", u(s.frames_recovered));
  field("interpolation_delay_ms", num(s.interpolation_delay_ms));
  field("interpolation_delay_max_ms", num(s.interpolation_delay_max_ms));
  field("duration_s", num(s.duration_s));
  field("profile", json_string(s.profile));
  field("transport", json_string(s.transport));
  field("link", json_string(s.link));
  field("scenario", json_string(s.scenario));
  field("bandwidth_bps", u(s.bandwidth_bps));
  return j + "}";
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
  row("frames ok (on time) %", num(s.frames_ok_pct));
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
  row("loadtest cpu %", num(s.loadtest_cpu_pct));
}

}  // namespace ocean::loadtest
