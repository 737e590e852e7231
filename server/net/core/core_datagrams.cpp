// SessionCore, UDP side: every datagram is verified, matched to a proven session (or proves one
// with its cookie), and answered never larger than it before proof; nothing is allocated per
// datagram.
#include "session_core.hpp"

#include "core_helpers.hpp"
#include "frame_records.hpp"
#include "message_builders.hpp"
#include "server_log.hpp"
#include "verify_message.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstring>

namespace ocean::server {

using core::cookie_endpoint;

void SessionCore::drop_datagram(protocol::Reason reason, const asio::ip::udp::endpoint& sender) {
  datagram_rejects_[static_cast<std::size_t>(reason) % datagram_rejects_.size()]->inc();
  if (spdlog::should_log(spdlog::level::debug)) log_reject("udp", endpoint_text(sender), protocol::to_string(reason), true);
}

void SessionCore::on_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& sender,
                              const Instant& now) {
  if (bytes.size() > datagram_.size()) return drop_datagram(protocol::Reason::oversized, sender);
  std::memcpy(datagram_.data(), bytes.data(), bytes.size());  // verify_message needs 8-byte alignment
  const std::span<const std::uint8_t> aligned(datagram_.data(), bytes.size());
  const protocol::Verified verified = protocol::verify_message(aligned, {protocol::Sender::client, wire::Transport::udp});
  const wire::Message* message = verified.message;
  const std::uint64_t session_id = verified ? core::named_session(*message) : 0;
  Session* found = sessions_.find(session_id);
  bool proven = found && found->udp && found->udp->endpoint() == sender;
  if (!proven) {
    unproven_bytes_in_ += bytes.size();
    host_.metrics.udp_unproven_bytes_in.inc(static_cast<double>(bytes.size()));
  }
  if (!verified) return drop_datagram(verified.reason, sender);
  if (!found) return drop_datagram(protocol::Reason::bad_session, sender);
  Session& session = *found;
  if (!proven) proven = reclaim_udp(session, *message, sender);
  if (message->body_type() == wire::Body::UdpHello)
    return on_udp_hello(session, *message, bytes.size(), proven, sender, now);
  if (!proven) return drop_datagram(protocol::Reason::bad_session, sender);  // address not proven
  if (const protocol::Reason r = protocol::check_udp_sender(*message, session.id, session.cookie); r != protocol::Reason::ok)
    return drop_datagram(r, sender);
  session.last_heard_s = session.udp_heard_s = now.monotonic_s;
  on_session_message(session, *message, *session.udp, now);
}

void SessionCore::on_udp_hello(Session& session, const wire::Message& message, std::size_t datagram_bytes, bool proven,
                               const asio::ip::udp::endpoint& sender, const Instant& now) {
  // Stateless first: the MAC binds the cookie to this IP; then the session's own cookie.
  const auto* cookie = message.body_as_UdpHello()->cookie();
  const CookieCheck check = verify_cookie(host_.cookie_key, std::span<const std::uint8_t>(cookie->data(), cookie->size()),
                                          cookie_endpoint(sender.address()), now.unix_ms);
  if (check.status != CookieStatus::ok || check.session_id != session.id)
    return drop_datagram(protocol::Reason::bad_cookie, sender);
  if (const protocol::Reason r = protocol::check_udp_sender(message, session.id, session.cookie); r != protocol::Reason::ok)
    return drop_datagram(r, sender);
  // A live proven address stays: the cookie travels in every datagram, so whoever sees the
  // traffic can replay it from another port of the client's IP (the cookie cannot bind the port,
  // which a NAT may change). A real rebinding leaves the old address silent; a replay does not.
  const bool moving = !proven && session.udp.has_value();
  if (moving && now.monotonic_s - session.udp_heard_s < rebind_quiet_s(session)) {
    host_.metrics.udp_rebinds_refused.inc();
    log_limited(spdlog::level::info, "udp_rebind_refused", endpoint_text(sender),
                "udp rebind refused session={} peer={} proven={}: the proven address is still live", session.id,
                endpoint_text(sender), session.udp->peer());
    return;
  }
  session.last_heard_s = session.udp_heard_s = now.monotonic_s;
  const protocol::Bytes ready = protocol::message_datagram(protocol::encode(protocol::UdpReady{session.id}));
  if (!proven) {  // always smaller than the padded UdpHello
    unproven_bytes_out_ += ready.size();
    host_.metrics.udp_unproven_bytes_out.inc(static_cast<double>(ready.size()));
  }
  if (ready.size() <= datagram_bytes) host_.datagrams.send_datagram(ready, sender);
  if (proven) return;
  if (moving) {
    host_.metrics.udp_rebinds.inc();
    session.udp_moved_from = session.udp->endpoint();
  }
  log_limited(spdlog::level::info, "udp_proven", endpoint_text(sender), "udp {} session={} peer={}",
              moving ? "moved" : "proven", session.id, endpoint_text(sender));
  session.udp.emplace(host_.datagrams, sender);
  update_client_gauges();
}

// A replay can still win while the client is silent a moment (a stalled phone, a burst of loss):
// the address it took the stream from is the client's, so a valid datagram from there takes the
// stream back at once, and the session's next move waits longer. A NAT that really rebound never
// sends from the old port again.
bool SessionCore::reclaim_udp(Session& session, const wire::Message& message, const asio::ip::udp::endpoint& sender) {
  if (!session.udp || session.udp_moved_from != sender) return false;
  if (protocol::check_udp_sender(message, session.id, session.cookie) != protocol::Reason::ok) return false;
  host_.metrics.udp_rebinds_reclaimed.inc();
  log_limited(spdlog::level::warn, "udp_rebind_reclaimed", endpoint_text(sender),
              "udp rebind undone session={} peer={} from={}: the address it moved away from spoke again", session.id,
              endpoint_text(sender), session.udp->peer());
  session.udp.emplace(host_.datagrams, sender);
  session.udp_moved_from.reset();
  ++session.udp_reclaims;
  return true;
}

double SessionCore::rebind_quiet_s(const Session& session) const {
  double quiet = options_.udp_rebind_quiet_s;
  for (int i = 0; i < session.udp_reclaims && quiet < options_.udp_rebind_quiet_max_s; ++i) quiet *= 4.0;
  return std::min(quiet, options_.udp_rebind_quiet_max_s);
}

}  // namespace ocean::server
