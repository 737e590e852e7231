// ClientSessionConfig: what a client asks for in its Hello and the timings of its protocol timers.
// A zero-initialised field keeps its default; the defaults are PROTOCOL.md's recommendations.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "decode_memo.hpp"
#include "parallel_for.hpp"

#include "ocean_generated.h"

namespace ocean::client {

struct ClientSessionConfig {
  // Hello (PROTOCOL.md 8).
  std::uint8_t profile_id = 0;  // 0 = the server's choice
  std::uint64_t bandwidth_bps = 0;
  wire::Transport transport = wire::Transport::udp;
  std::string client_name = "ocean-client";

  // Timers, seconds (PROTOCOL.md 5 and 7).
  double ack_interval_s = 0.1;          // at least one Ack this often while frames complete
  double udp_hello_interval_s = 0.25;   // UdpHello retry
  // No UdpReady by then, or no datagram for this long on UDP: SetTransport{tcp}, once a Ping on
  // TCP is answered (a stalled server silences both paths: then nothing changes).
  double udp_proof_timeout_s = 2.0;
  double udp_silence_timeout_s = 2.0;
  // No datagram for this long on UDP: UdpHello again (every udp_hello_interval_s) until one comes
  // or the silence timeout. A NAT that moved our port is repaired this way: the server moves the
  // stream once the old address has been quiet a while (PROTOCOL.md 5, step 4).
  double udp_reprove_after_s = 0.75;
  // After a fallback to TCP, UDP is tried again (PROTOCOL.md 5, step 6): a round of UdpHellos as
  // long as a proof may take, udp_retry_after_s after the fallback, then after twice that, and so
  // on up to udp_retry_max_s; a UdpReady in a round sends SetTransport{udp} and deltas come on UDP
  // again. A phone out of a tunnel, or a server back from a stall, so gets its UDP stream back.
  // The wait starts over once UDP has carried the stream for udp_retry_max_s.
  double udp_retry_after_s = 1.0;
  double udp_retry_max_s = 30.0;
  double ping_interval_s = 1.0;         // RTT probe, also the keepalive when no frames arrive
  double keyframe_retry_s = 1.0;        // at most one KeyframeRequest this often (servers rate-limit too)
  double startup_keyframe_after_s = 1.0;  // no frame this long after the Welcome: KeyframeRequest{startup}
  std::uint32_t stuck_ticks = 32;       // no frame completed for this many ticks: KeyframeRequest
  double idle_timeout_s = 10.0;         // nothing valid received for this long: close
  // PROTOCOL.md 5: a client that receives a bad TCP message closes. Tests turn this off to check
  // that a rejected message changes nothing.
  bool close_on_bad_tcp_message = true;

  // Many clients of one process (a load test) may share decoding work: given the Welcome's stream,
  // return a memo for it (or nullptr). Results are identical either way.
  std::function<codec::DecodeMemo*(const codec::StreamConfig&)> decode_memo;
  // Threads the decoder may spread each frame's transforms over (a WorkerPool's run); results are
  // identical either way. Used from the session's thread only, one frame at a time.
  codec::ParallelFor decode_parallel;
};

}  // namespace ocean::client
