// SimClient: one simulated client of a load run - its connection, its tally of frames, and the
// counters its ended sessions left behind (a reconnect starts a new session).
#pragma once

#include "tick.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "client_connection.hpp"
#include "client_figures.hpp"
#include "client_tally.hpp"
#include "load_summary.hpp"
#include "receive_rate.hpp"

namespace ocean::loadtest {

// What a client's sessions reported that explains lost frames.
struct SessionCounts {
  std::uint64_t codec_rejected = 0, messages_rejected = 0, keyframe_requests = 0, transport_fallbacks = 0,
                frames_recovered = 0;
  std::array<std::uint64_t, client::kChunkErrorCount> codec_by_reason{};
  void add(const client::ClientStats& s) {
    for (std::size_t r = 0; r < codec_by_reason.size(); ++r) codec_by_reason[r] += s.chunks_rejected_by_codec[r];
    codec_rejected += s.codec_rejected_total();
    messages_rejected += s.rejected_total();
    keyframe_requests += s.keyframe_requests_sent;
    transport_fallbacks += s.transport_fallbacks;
    frames_recovered += s.frames_recovered;
  }
};

// Datagrams a session took in, valid or not (each cost the link its bytes and an IP/UDP header).
inline std::uint64_t udp_datagrams_in(const client::ClientStats& s) { return s.udp.messages_in + s.udp.rejected; }

struct SimClient {
  std::shared_ptr<client::ClientConnection> connection;
  std::optional<ClientTally> tally;
  std::optional<Tick> welcome_tick;
  std::uint64_t closed_bytes = 0, closed_keyframes = 0, closed_datagrams = 0;
  SessionCounts closed;
  bool session_ended = false;  // the connection keeps its last session after it ended: counted in closed_*
  double started_s = 0.0;                // steady time of its first connection attempt
  std::optional<double> first_frame_s;   // steady arrival of its first complete frame within the bound
  ReceiveRate traffic;

  void end_session(const client::ClientSession& s) {
    session_ended = true;
    closed_bytes += s.stats().tcp.bytes_in + s.stats().udp.bytes_in;
    closed_keyframes += s.stats().keyframes_complete;
    closed_datagrams += udp_datagrams_in(s.stats());
    closed.add(s.stats());
  }
  const client::ClientSession* live_session() const {
    return connection && !session_ended ? connection->session() : nullptr;
  }
  // Application bytes received after the link model, TCP and UDP, envelopes included.
  std::uint64_t bytes() const {
    std::uint64_t b = closed_bytes;
    if (const auto* s = live_session()) b += s->stats().tcp.bytes_in + s->stats().udp.bytes_in;
    return b;
  }
  std::uint64_t udp_datagrams() const {
    std::uint64_t n = closed_datagrams;
    if (const auto* s = live_session()) n += udp_datagrams_in(s->stats());
    return n;
  }
  std::uint64_t keyframes() const {
    std::uint64_t k = closed_keyframes;
    if (const auto* s = live_session()) k += s->stats().keyframes_complete;
    return k;
  }
  // Adds its keyframes, reconnects and every session's counters to the summary.
  void add_counters_to(LoadSummary& s) const;
  ClientConnectionFacts connection_facts() const;
};

}  // namespace ocean::loadtest
