#include "sim_client.hpp"

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
