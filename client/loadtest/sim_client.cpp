#include "sim_client.hpp"

#include <algorithm>
#include <string>

namespace ocean::loadtest {

void SimClient::add_counters_to(LoadSummary& s) const {
  s.keyframes += keyframes();
  SessionCounts counts = closed;
  if (const auto* session = live_session()) counts.add(session->stats());
  s.chunks_rejected_by_codec += counts.codec_rejected;
  s.messages_rejected += counts.messages_rejected;
  s.keyframe_requests += counts.keyframe_requests;
  s.transport_fallbacks += counts.transport_fallbacks;
  s.frames_recovered += counts.frames_recovered;
  for (std::size_t r = 0; r < counts.codec_by_reason.size(); ++r)
    if (counts.codec_by_reason[r])
      s.codec_rejections[std::string(codec::to_string(static_cast<codec::ChunkError>(r)))] += counts.codec_by_reason[r];
  if (connection && connection->counters().connects > 1) s.reconnects += connection->counters().connects - 1;
  if (welcome_tick) ++s.clients_welcomed;
  // "server refused the Hello: <reason>: <text>" (ClientSession): counted by reason, as the text
  // may carry numbers (a retry hint) that would make every client its own row.
  static constexpr std::string_view kRefused = "server refused the Hello: ";
  const auto reason_in = [](const std::string& text) {
    return text.substr(kRefused.size(), text.find(':', kRefused.size()) - kRefused.size());
  };
  const std::string why = connection ? connection->counters().last_close_reason : std::string();
  const bool refused = why.starts_with(kRefused);
  if (connection && !connection->connected() && refused) ++s.refusals[reason_in(why)];
  // A client refused earlier that was back in a handshake, as the refusal's hint asked, at the end.
  const std::string earlier = connection ? connection->counters().last_refusal : std::string();
  if (!welcome_tick) {
    if (refused) ++s.not_welcomed["refused: " + reason_in(why)];
    else if (earlier.starts_with(kRefused)) ++s.not_welcomed["refused: " + reason_in(earlier) + ", then retrying"];
    else if (why.empty()) ++s.not_welcomed[connection ? "connecting" : "never started"];
    else ++s.not_welcomed[why.substr(0, std::min<std::size_t>(why.find(':'), 48))];
  }
}

ClientConnectionFacts SimClient::connection_facts() const {
  ClientConnectionFacts f;
  if (first_frame_s) f.ttff_s = *first_frame_s - started_s;
  if (traffic.has_steady_window()) f.peak_kbps = traffic.peak_kbps();
  f.startup_peak_kbps = traffic.startup_peak_kbps();
  f.calm_kbps = traffic.calm_kbps();
  return f;
}

}  // namespace ocean::loadtest
