// ClientSession's own clock: the messages it sends unprompted (acks, UDP proofs, pings, keyframe
// requests, the fallback to TCP) and update()/next_due(), which decide when. Apart from the message
// handling so the timing rules (PROTOCOL.md section 7) read in one place.
#include "client_session.hpp"

#include <algorithm>
#include <limits>

#include "ack_window.hpp"
#include "message_builders.hpp"
#include "wire_limits.hpp"

namespace ocean::client {

wire::Transport ClientSession::control_path() const {
  return path_ == Path::udp ? wire::Transport::udp : wire::Transport::tcp;
}

void ClientSession::send(const protocol::Bytes& bytes, wire::Transport transport) {
  if (transport == wire::Transport::tcp) {
    ++stats_.tcp.messages_out;
    stats_.tcp.bytes_out += bytes.size();
    if (events_.send_tcp) events_.send_tcp(bytes);
  } else {
    if (!protocol::fits_datagram(bytes)) return;  // never happens for the messages a client sends
    ++stats_.udp.messages_out;
    stats_.udp.bytes_out += bytes.size();
    if (events_.send_udp) events_.send_udp(bytes);
  }
}

void ClientSession::send_ack(double now) {
  const auto& window = decoder_->ack_window();
  next_ack_ = now + config_.ack_interval_s;
  if (!window) return;
  protocol::Ack ack;
  ack.session_id = welcome_->session_id;
  if (control_path() == wire::Transport::udp) ack.cookie = welcome_->udp_cookie;
  ack.latest_tick = window->latest_tick;
  ack.ack_bits = window->bits;
  send(protocol::encode(ack), control_path());
  ++stats_.acks_sent;
  ack_pending_ = false;
}

void ClientSession::send_udp_hello(double now) {
  protocol::UdpHello hello;
  hello.session_id = welcome_->session_id;
  hello.cookie = welcome_->udp_cookie;
  send(protocol::encode(hello), wire::Transport::udp);
  ++stats_.udp_hellos_sent;
  next_udp_hello_ = now + config_.udp_hello_interval_s;
}

void ClientSession::send_ping(double now, wire::Transport transport) {
  protocol::Ping ping;
  ping.session_id = welcome_->session_id;
  if (transport == wire::Transport::udp) ping.cookie = welcome_->udp_cookie;
  ping.seq = ++ping_seq_;
  ping.client_time_us = static_cast<std::uint64_t>(std::max(0.0, now) * 1e6);
  send(protocol::encode(ping), transport);
  ++stats_.pings_sent;
  next_ping_ = now + config_.ping_interval_s;
}

bool ClientSession::tcp_answers(double now) {
  if (tcp_probe_.answered) return true;
  if (tcp_probe_.seq == 0 || now - tcp_probe_.sent_s >= config_.ping_interval_s) {
    send_ping(now, wire::Transport::tcp);
    tcp_probe_ = TcpProbe{ping_seq_, now, false};
  }
  return false;
}

void ClientSession::request_keyframe(wire::KeyframeReason reason, double now) {
  if (now - last_keyframe_request_ < config_.keyframe_retry_s) return;
  last_keyframe_request_ = now;
  protocol::KeyframeRequest request;
  request.session_id = welcome_->session_id;
  request.reason = reason;
  send(protocol::encode(request), wire::Transport::tcp);  // keyframes come on TCP; ask there reliably
  ++stats_.keyframe_requests_sent;
}

void ClientSession::fall_back_to_tcp(double now) {
  send(protocol::encode(protocol::SetTransport{wire::Transport::tcp}), wire::Transport::tcp);
  ++stats_.transport_fallbacks;
  path_ = Path::tcp;
  last_progress_ = std::max(last_progress_, now);  // the server answers with a keyframe on TCP
  // A fallback soon after a return means UDP still fails: wait longer before the next try.
  back_off_udp_retry(now);
  udp_retry_round_end_ = 0.0;
}

// The first try after udp_retry_after_s, then each twice as late, up to udp_retry_max_s.
void ClientSession::back_off_udp_retry(double now) {
  udp_retry_delay_s_ = udp_retry_delay_s_ == 0.0 ? config_.udp_retry_after_s
                                                 : std::min(2.0 * udp_retry_delay_s_, config_.udp_retry_max_s);
  next_udp_retry_ = now + udp_retry_delay_s_;
}

bool ClientSession::may_retry_udp() const {
  return path_ == Path::tcp && config_.transport == wire::Transport::udp && welcome_ && welcome_->udp_port != 0 &&
         config_.udp_retry_after_s > 0.0;
}

void ClientSession::retry_udp(double now) {
  if (udp_retry_round_end_ == 0.0) {
    if (now < next_udp_retry_) return;
    udp_retry_round_end_ = now + config_.udp_proof_timeout_s;
    return send_udp_hello(now);
  }
  if (now >= udp_retry_round_end_) {  // no UdpReady: the path still fails
    udp_retry_round_end_ = 0.0;
    back_off_udp_retry(now);
  } else if (now >= next_udp_hello_) {
    send_udp_hello(now);
  }
}

void ClientSession::return_to_udp(double now) {
  send(protocol::encode(protocol::SetTransport{wire::Transport::udp}), wire::Transport::tcp);
  ++stats_.transport_returns;
  path_ = Path::udp;
  last_udp_rx_ = udp_since_ = now;
  udp_retry_round_end_ = 0.0;
  tcp_probe_ = TcpProbe{};
}

void ClientSession::update(double now) {
  if (state_ == State::awaiting_welcome && now - last_rx_ >= config_.idle_timeout_s)
    return close("no Welcome within idle_timeout_s");
  if (state_ != State::streaming) return;
  if (now - last_rx_ >= config_.idle_timeout_s) return close("the server was silent for idle_timeout_s");

  if (path_ == Path::udp && udp_retry_delay_s_ > 0.0 && now - udp_since_ >= config_.udp_retry_max_s)
    udp_retry_delay_s_ = 0.0;  // UDP has held a while: a later fallback starts with a short wait
  if (may_retry_udp()) retry_udp(now);
  if (path_ == Path::udp_proving || path_ == Path::udp) {
    // No UdpReady in time, or a silent UDP path: TCP only if TCP answers meanwhile. A server
    // that stalls (overload, a pause) silences both paths, and a fallback would only add a
    // keyframe to its load; the client keeps proving UDP all the while.
    const bool proving = path_ == Path::udp_proving;
    const double waited = now - (proving ? udp_proof_started_ : last_udp_rx_);
    const double limit = proving ? config_.udp_proof_timeout_s : config_.udp_silence_timeout_s;
    if (waited < limit) tcp_probe_ = TcpProbe{};
    if (waited >= limit && tcp_answers(now))
      fall_back_to_tcp(now);
    else if ((proving || waited >= config_.udp_reprove_after_s) && now >= next_udp_hello_)
      send_udp_hello(now);
  }

  if (now >= next_ack_) {
    const bool live = now - last_progress_ < 1.0;  // frames still completing: keep acking
    if (decoder_->newest_complete() && (ack_pending_ || live))
      send_ack(now);
    else
      next_ack_ = now + config_.ack_interval_s;
  }
  if (now >= next_ping_) send_ping(now, control_path());

  if (!decoder_->newest_complete()) {
    if (now - welcome_at_ >= config_.startup_keyframe_after_s) request_keyframe(wire::KeyframeReason::startup, now);
  } else if (now - last_progress_ >= config_.stuck_ticks * welcome_->tick_period_s) {
    request_keyframe(last_chunk_error_ == codec::ChunkError::unknown_baseline ? wire::KeyframeReason::lost_baseline
                                                                              : wire::KeyframeReason::incomplete_frame,
                     now);
  }
}

double ClientSession::next_due() const {
  if (state_ == State::awaiting_welcome) return last_rx_ + config_.idle_timeout_s;
  if (state_ != State::streaming) return std::numeric_limits<double>::infinity();
  double due = std::min({last_rx_ + config_.idle_timeout_s, next_ack_, next_ping_});
  if (path_ == Path::udp_proving)
    due = std::min({due, next_udp_hello_, udp_proof_started_ + config_.udp_proof_timeout_s});
  else if (path_ == Path::udp)
    due = std::min({due, last_udp_rx_ + config_.udp_silence_timeout_s,
                    std::max(last_udp_rx_ + config_.udp_reprove_after_s, next_udp_hello_)});
  else if (may_retry_udp())
    due = std::min(due, udp_retry_round_end_ == 0.0 ? next_udp_retry_ : std::min(udp_retry_round_end_, next_udp_hello_));
  if (path_ == Path::udp && udp_retry_delay_s_ > 0.0) due = std::min(due, udp_since_ + config_.udp_retry_max_s);
  const double keyframe_at = decoder_->newest_complete()
                                 ? last_progress_ + config_.stuck_ticks * welcome_->tick_period_s
                                 : welcome_at_ + config_.startup_keyframe_after_s;
  return std::min(due, std::max(keyframe_at, last_keyframe_request_ + config_.keyframe_retry_s));
}

}  // namespace ocean::client
