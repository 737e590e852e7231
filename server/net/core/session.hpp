// Session: one connected client as the SessionCore keeps it: its stream link (TCP), the profile
// stream it watches, its proven UDP address, its baselines, and the timers of keys, bandwidth and silence.
#pragma once

#include "baseline_tracker.hpp"
#include "profile_stream.hpp"
#include "link.hpp"
#include "token_bucket.hpp"
#include "udp_cookie.hpp"

#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace ocean::server {

// A single-chunk frame sent on UDP, kept to be copied into the next datagrams until acked.
struct RecentFrame {
  Tick tick = 0;
  std::shared_ptr<const codec::EncodedFrame> frame;
};

struct Session {
  std::uint64_t id = 0;
  std::shared_ptr<StreamLink> link;
  bool welcomed = false;
  ProfileStream* stream = nullptr;          // set by the Welcome
  Cookie cookie{};
  bool wants_udp = false;                   // Hello / SetTransport
  std::optional<UdpLink> udp;               // the address a UdpHello proved
  double udp_heard_s = 0.0;                 // the last valid datagram from that address
  // The address the last rebinding moved the stream away from: if it speaks again the move was a
  // replay (a NAT that rebinds leaves the old port silent), and the stream goes back to it.
  std::optional<asio::ip::udp::endpoint> udp_moved_from;
  int udp_reclaims = 0;                     // how often that happened: each makes the next move wait longer
  bool ending = false;                      // Bye or Error sent, closing after a flush
  bool admitted = false;                    // counted by Admission (its address's connections)
  int token_failures = 0;                   // ParamChanges with a wrong admin token
  bool change_waiting = false;              // its ParamChange or HeightQuery waits in the admin queue
  bool admin_proven = false;                // it sent the right admin token once
  TokenBucket height_queries{0.0, 0.0, 0.0};  // HeightQuery rate (SessionCoreOptions), set at the first
  TokenBucket query_refusals{0.0, 0.0, 0.0};  // refusals it may ignore (as fast), before it is closed
  BaselineTracker baselines;
  std::deque<RecentFrame> recent_udp;       // the last kMaxUdpRedundancy single-chunk UDP frames
  std::uint64_t tcp_frames_mark = 0;        // link->enqueued_total() after the last frame queued on it
  bool tcp_frames_pending = false;          // ... and the link has not written them through yet
  bool closed = false;                      // its link closed (the core erased it; a walk may still hold it)
  bool need_key = true;                     // the next frame must be a key
  bool key_requested = false;               // a KeyframeRequest waits for its rate limit
  bool rekey = false;                       // its key root is merged: this key tick's key, paid for
  double last_key_s = -std::numeric_limits<double>::infinity();
  TokenBucket udp_bucket{0.0, 0.0, 0.0};
  double bytes_per_s = 0.0;                 // the client's budget; 0 = unlimited
  double opened_s = 0.0;
  double last_heard_s = 0.0;

  bool on_udp() const { return wants_udp && udp.has_value(); }
  // Where frames go now: the metrics and log label.
  std::string_view transport() const { return on_udp() ? udp->transport() : link->transport(); }
  const std::string& peer() const { return link->peer(); }
};

}  // namespace ocean::server
