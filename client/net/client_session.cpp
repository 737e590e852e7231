// ClientSession: what the server sends and how the session answers it (PROTOCOL.md sections 5-7);
// what the client sends on its own clock is in client_session_timers.cpp.
#include "client_session.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stream_wire.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "stream_config.hpp"
#include "wire_limits.hpp"

namespace ocean::client {
namespace {

// Refusals that mean the payload itself is broken (not merely late, duplicated or baseline-less).
bool is_decode_error(codec::ChunkError e) {
  switch (e) {
    case codec::ChunkError::truncated:
    case codec::ChunkError::oversized:
    case codec::ChunkError::unknown_version:
    case codec::ChunkError::bad_flags:
    case codec::ChunkError::wrong_dimensions:
    case codec::ChunkError::bad_range:
    case codec::ChunkError::checksum_mismatch:
    case codec::ChunkError::bad_value:
    case codec::ChunkError::coverage_mismatch:
      return true;
    default:
      return false;
  }
}

}  // namespace

ClientSession::ClientSession(ClientSessionConfig config, ClientSessionEvents events)
    : config_(std::move(config)), events_(std::move(events)), max_message_bytes_(protocol::kDefaultMaxMessageBytes) {}

void ClientSession::start(double now) {
  if (state_ != State::idle) return;
  state_ = State::awaiting_welcome;
  last_rx_ = now;
  protocol::Hello hello;
  hello.profile_id = config_.profile_id;
  hello.bandwidth_bps = config_.bandwidth_bps;
  hello.transport = config_.transport;
  hello.client_name = config_.client_name.substr(0, protocol::kMaxClientNameBytes);
  send(protocol::encode(hello), wire::Transport::tcp);
  hello_sent_ = now;
}

std::span<const std::uint8_t> ClientSession::aligned(std::span<const std::uint8_t> bytes) {
  if (reinterpret_cast<std::uintptr_t>(bytes.data()) % 8 == 0) return bytes;
  scratch_.assign(bytes.begin(), bytes.end());
  return scratch_;
}

void ClientSession::on_tcp_message(std::span<const std::uint8_t> bytes, double now) {
  if (state_ == State::idle || state_ == State::closed) return;
  stats_.tcp.bytes_in += bytes.size();
  const protocol::Verified result =
      protocol::verify_message(aligned(bytes), {protocol::Sender::server, wire::Transport::tcp, max_message_bytes_});
  if (!result) return reject(result, wire::Transport::tcp, now);
  ++stats_.tcp.messages_in;
  last_rx_ = now;
  handle(*result.message, wire::Transport::tcp, now);
}

void ClientSession::on_udp_datagram(std::span<const std::uint8_t> bytes, double now) {
  if (state_ != State::streaming) return;
  stats_.udp.bytes_in += bytes.size();
  // Server datagrams start with their kind (PROTOCOL.md 3): frame records, or a message.
  if (bytes.empty() || bytes.size() > protocol::kMaxDatagram || bytes[0] > 1) {
    count_rejection(bytes.empty() ? protocol::Reason::empty
                    : bytes.size() > protocol::kMaxDatagram ? protocol::Reason::oversized
                                                             : protocol::Reason::unknown_message_type);
    ++stats_.udp.rejected;
    return;
  }
  if (bytes[0] == static_cast<std::uint8_t>(protocol::DatagramKind::frames)) {
    ++stats_.udp.messages_in;
    return handle_frames(bytes.subspan(1), wire::Transport::udp, now);
  }
  const protocol::Verified result = protocol::verify_message(
      aligned(bytes.subspan(1)), {protocol::Sender::server, wire::Transport::udp, protocol::kMaxDatagram});
  if (!result) return reject(result, wire::Transport::udp, now);
  ++stats_.udp.messages_in;
  last_rx_ = now;
  last_udp_rx_ = now;
  handle(*result.message, wire::Transport::udp, now);
}

void ClientSession::reject(const protocol::Verified& result, wire::Transport transport, double /*now*/) {
  count_rejection(result.reason);
  if (transport == wire::Transport::tcp) {
    ++stats_.tcp.rejected;
    if (config_.close_on_bad_tcp_message) close("bad TCP message from the server: " + protocol::describe(result));
  } else {
    ++stats_.udp.rejected;  // UDP: dropped, counted, nothing else (PROTOCOL.md 4)
  }
}

// A verified message that is well-formed but out of place here (or a chunk of another profile):
// counted with its reason, changes nothing.
void ClientSession::count_rejection(protocol::Reason reason) {
  ++stats_.rejected_by_reason[static_cast<std::size_t>(reason)];
}

void ClientSession::handle(const wire::Message& message, wire::Transport transport, double now) {
  switch (message.body_type()) {
    case wire::Body::Welcome:
      if (state_ != State::awaiting_welcome) return count_rejection(protocol::Reason::unexpected_message);
      return handle_welcome(protocol::read(*message.body_as_Welcome()), now);
    case wire::Body::UdpReady: {
      const bool retrying = path_ == Path::tcp && udp_retry_round_end_ > 0.0;
      if (state_ != State::streaming || transport != wire::Transport::udp || (path_ == Path::tcp && !retrying))
        return count_rejection(protocol::Reason::unexpected_message);
      if (message.body_as_UdpReady()->session_id() != welcome_->session_id) {
        return count_rejection(protocol::Reason::bad_session);
      }
      if (retrying) return return_to_udp(now);
      if (path_ == Path::udp_proving) udp_since_ = now;
      path_ = Path::udp;  // a repeated UdpReady changes nothing
      return;
    }
    case wire::Body::FrameData: {
      if (state_ != State::streaming) return count_rejection(protocol::Reason::unexpected_message);
      const auto* frames = message.body_as_FrameData()->frames();  // required and non-empty (verified)
      return handle_frames({frames->data(), frames->size()}, transport, now);
    }
    case wire::Body::SceneUpdate: {
      if (state_ != State::streaming) return count_rejection(protocol::Reason::unexpected_message);
      const protocol::SceneUpdate update = protocol::read(*message.body_as_SceneUpdate());
      add_scene(update.effective_tick, update.serial, update.scene);
      if (state_ != State::streaming) return;
      // A vessel command's fleet, from its tick on (ignored by a stream without a wake lattice).
      if (update.vessels && decoder_->config().has_wake()) decoder_->set_vessels(*update.vessels, update.effective_tick);
      scene_ = update.scene;
      if (events_.on_scene_update) events_.on_scene_update(update);
      return;
    }
    case wire::Body::Pong:
      if (state_ != State::streaming) return count_rejection(protocol::Reason::unexpected_message);
      return handle_pong(protocol::read(*message.body_as_Pong()), transport, now);
    case wire::Body::Error: {
      ++stats_.errors_received;
      const protocol::Error error = protocol::read(*message.body_as_Error());
      const std::string what = std::string(protocol::to_string(error.code)) + ": " + error.text;
      last_error_ = what;
      // Before the Welcome an Error is a refusal and the server closes; after it, a refused request.
      if (state_ == State::awaiting_welcome) {
        refusal_ = error.code;
        close("server refused the Hello: " + what);
      }
      return;
    }
    case wire::Body::Bye: {
      const protocol::Bye bye = protocol::read(*message.body_as_Bye());
      return close(std::string("server said Bye (") + wire::EnumNameByeReason(bye.reason) + "): " + bye.text);
    }
    default:
      return count_rejection(protocol::Reason::unexpected_message);  // the verifier already refuses client-only types; kept for safety
  }
}

void ClientSession::handle_welcome(const protocol::Welcome& welcome, double now) {
  const codec::StreamConfig config = codec::decoder_config(welcome);
  if (const std::string problem = codec::validate(config); !problem.empty()) {
    ++stats_.rejected_by_reason[static_cast<std::size_t>(protocol::Reason::out_of_range)];
    return close("Welcome.stream is not decodable by this client's codec: " + problem);
  }
  codec::DecoderOptions options;
  // Keyframes on TCP may use chunks up to the session's message limit.
  options.max_payload = std::max(codec::kDefaultMaxPayload, protocol::max_chunk_payload(welcome.max_message_bytes));
  options.history_ticks = protocol::kMaxBaselineGap;
  if (config_.decode_memo) options.memo = config_.decode_memo(config);
  options.parallel = config_.decode_parallel;
  try {
    decoder_ = std::make_unique<codec::Decoder>(config, options);
    if (config.has_wake()) decoder_->set_vessels(welcome.vessels);  // their hulls force the wake
  } catch (const std::invalid_argument& e) {
    return close(std::string("cannot build the decoder for Welcome.stream: ") + e.what());
  }
  welcome_ = welcome;
  add_scene(0, welcome.scene_serial, welcome.scene);  // in force since before any frame it will get
  if (state_ == State::closed) return;
  scene_ = welcome.scene;
  max_message_bytes_ = welcome.max_message_bytes;
  state_ = State::streaming;
  welcome_at_ = now;
  stats_.handshake_rtt_s = now - hello_sent_;
  last_progress_ = now;
  last_udp_rx_ = now;
  next_ack_ = now + config_.ack_interval_s;
  if (events_.on_welcome) events_.on_welcome(welcome);
  if (state_ != State::streaming) return;  // the owner closed us from the callback
  if (config_.transport == wire::Transport::udp && welcome.udp_port != 0) {
    path_ = Path::udp_proving;
    udp_proof_started_ = now;
    send_udp_hello(now);
  } else {
    path_ = Path::tcp;
  }
  // The first Ping goes from the next update(), stamped after the decoder's build above (seconds
  // for a wake's history), which would otherwise count as round trip.
  next_ping_ = now;
}

void ClientSession::add_scene(Tick from, std::uint32_t serial, const protocol::SceneParams& scene) {
  try {
    decoder_->add_scene(from, static_cast<std::uint8_t>(serial), scene);
  } catch (const std::invalid_argument& e) {
    close(std::string("the server's scene does not fit the stream: ") + e.what());
  }
}

// Oldest first: a copy of a frame whose own datagram was lost completes before the newest frame,
// so each is delivered in order; copies of frames already held are skipped, not refused.
void ClientSession::handle_frames(std::span<const std::uint8_t> block, wire::Transport transport, double now) {
  const protocol::FrameBlockResult parsed = protocol::decode_frame_block(block, records_);
  if (!parsed) {
    count_rejection(parsed.reason);
    if (transport == wire::Transport::tcp) {
      ++stats_.tcp.rejected;
      if (config_.close_on_bad_tcp_message) close("bad FrameData from the server: " + parsed.rule);
    } else {
      ++stats_.udp.rejected;
    }
    return;
  }
  if (transport == wire::Transport::udp) {
    last_rx_ = now;
    last_udp_rx_ = now;
  }
  // Acks go out from update() at most every ack_interval_s: on a thin uplink one Ack per frame
  // would cost more than half of a 32 kbit/s link.
  for (std::size_t i = 0; i < records_.size() && state_ == State::streaming; ++i) {
    const protocol::FrameRecord& record = records_[i];
    const bool last = i + 1 == records_.size();
    if (!last && decoder_->is_complete(record.tick)) {
      ++stats_.chunks_received;
      ++stats_.chunks_redundant;
      continue;
    }
    if (handle_record(record, now) && !last) ++stats_.frames_recovered;
  }
  // A key is acked at once: until the server hears of it, deltas come on TCP (larger).
  if (ack_pending_ && stats_.keyframes_complete > keys_acked_ && state_ == State::streaming) {
    keys_acked_ = stats_.keyframes_complete;
    send_ack(now);
  }
}

bool ClientSession::handle_record(const protocol::FrameRecord& record, double now) {
  ++stats_.chunks_received;
  const codec::ChunkView view{record.tick, record.baseline, record.key, record.index, record.count, record.payload};
  const bool was_complete = decoder_->is_complete(view.tick);
  const codec::ChunkError error = decoder_->accept(view);
  if (error != codec::ChunkError::ok) {
    ++stats_.chunks_rejected_by_codec[static_cast<std::size_t>(error)];
    last_chunk_error_ = error;
    if (is_decode_error(error)) request_keyframe(wire::KeyframeReason::decode_error, now);
    return false;
  }
  ++stats_.chunks_accepted;
  if (was_complete || !decoder_->is_complete(view.tick)) return false;
  ++stats_.frames_complete;
  if (view.key) ++stats_.keyframes_complete;
  if (!stats_.latest_tick || view.tick > *stats_.latest_tick) stats_.latest_tick = view.tick;
  last_progress_ = now;
  ack_pending_ = true;
  // Also a frame older than the one on show (its copy came late): a jitter buffer may still
  // play it before its time.
  const codec::ReconstructedFrame* frame = decoder_->just_completed();
  if (frame && frame->tick == view.tick && frame->complete) {
    ++stats_.frames_delivered;
    if (events_.on_frame) events_.on_frame(*frame, view.tick);
  }
  return true;
}

void ClientSession::handle_pong(const protocol::Pong& pong, wire::Transport transport, double now) {
  ++stats_.pongs_received;
  if (transport == wire::Transport::tcp && tcp_probe_.seq != 0 && pong.seq == tcp_probe_.seq) tcp_probe_.answered = true;
  stats_.last_pong_server_tick = pong.server_tick;
  const double rtt = now - static_cast<double>(pong.client_time_us) * 1e-6;
  if (!(rtt >= 0.0 && rtt < 60.0)) return;  // not a Ping of ours
  stats_.rtt_s = rtt;
  stats_.rtt_smoothed_s = stats_.rtt_smoothed_s == 0.0 ? rtt : stats_.rtt_smoothed_s + (rtt - stats_.rtt_smoothed_s) / 8.0;
}

void ClientSession::quit(double /*now*/) {
  if (state_ == State::closed) return;
  if (state_ != State::idle) send(protocol::encode(protocol::Bye{wire::ByeReason::client_quit, "client quit"}), wire::Transport::tcp);
  close("client quit");
}

void ClientSession::close(const std::string& why) {
  if (state_ == State::closed) return;
  state_ = State::closed;
  close_reason_ = why;
  if (events_.on_closed) events_.on_closed(why);
}

std::string_view to_string(ClientSession::State state) {
  switch (state) {
    case ClientSession::State::idle: return "idle";
    case ClientSession::State::awaiting_welcome: return "awaiting_welcome";
    case ClientSession::State::streaming: return "streaming";
    case ClientSession::State::closed: return "closed";
  }
  return "unknown";
}

std::string_view to_string(ClientSession::Path path) {
  switch (path) {
    case ClientSession::Path::tcp: return "tcp";
    case ClientSession::Path::udp_proving: return "udp_proving";
    case ClientSession::Path::udp: return "udp";
  }
  return "unknown";
}

}  // namespace ocean::client
