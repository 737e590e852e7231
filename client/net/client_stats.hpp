// ClientStats: the counters a ClientSession keeps - per-transport traffic, every rejection by its
// reason (protocol verification and codec), frames, keyframes, acks, and the round-trip estimate.
#pragma once

#include "tick.hpp"

#include <array>
#include <cstdint>
#include <optional>

#include "chunk_format.hpp"
#include "wire_reason.hpp"

namespace ocean::client {

inline constexpr std::size_t kChunkErrorCount = static_cast<std::size_t>(codec::ChunkError::unknown_scene) + 1;

struct TransportCounters {
  std::uint64_t messages_in = 0;   // verified
  std::uint64_t bytes_in = 0;      // every byte received, verified or not
  std::uint64_t rejected = 0;      // failed verification
  std::uint64_t messages_out = 0;
  std::uint64_t bytes_out = 0;
};

struct ClientStats {
  TransportCounters tcp, udp;
  std::array<std::uint64_t, protocol::kReasonCount> rejected_by_reason{};  // verification + session checks
  std::array<std::uint64_t, kChunkErrorCount> chunks_rejected_by_codec{};  // Decoder::accept refusals

  std::uint64_t chunks_received = 0;   // verified FrameChunks (bundled ones included)
  std::uint64_t chunks_redundant = 0;  // bundled copies of frames already complete, skipped
  std::uint64_t frames_recovered = 0;  // frames completed from a bundled copy (their first datagram was lost)
  std::uint64_t chunks_accepted = 0;   // taken by the decoder
  std::uint64_t frames_complete = 0;
  std::uint64_t keyframes_complete = 0;
  std::uint64_t frames_delivered = 0;  // handed to on_frame (late ones, older than the newest, too)
  std::optional<Tick> latest_tick;  // newest complete tick

  std::uint64_t acks_sent = 0;
  std::uint64_t keyframe_requests_sent = 0;
  std::uint64_t udp_hellos_sent = 0;
  std::uint64_t transport_fallbacks = 0;  // SetTransport{tcp} sent
  std::uint64_t transport_returns = 0;    // SetTransport{udp} sent: back on UDP after a fallback
  std::uint64_t pings_sent = 0;
  std::uint64_t pongs_received = 0;
  std::uint64_t errors_received = 0;      // Error messages from the server
  std::optional<Tick> last_pong_server_tick;

  double rtt_s = 0.0;         // last Pong
  double rtt_smoothed_s = 0.0;  // EWMA, 1/8 gain (RFC 6298 style); 0 until the first Pong
  double handshake_rtt_s = 0.0;  // Hello sent to Welcome received

  std::uint64_t rejected_total() const {
    std::uint64_t n = 0;
    for (auto v : rejected_by_reason) n += v;
    return n;
  }
  std::uint64_t codec_rejected_total() const {
    std::uint64_t n = 0;
    for (auto v : chunks_rejected_by_codec) n += v;
    return n;
  }
};

}  // namespace ocean::client
