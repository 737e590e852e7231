// ClientSession: the client's side of PROTOCOL.md as a pure state machine (netcode/yojimbo style):
// bytes and the time come in as arguments, bytes go out through callbacks; no sockets, no clocks.
// It owns the handshake, UDP proof and TCP fallback, the codec Decoder, acks, keyframe requests, pings.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "client_session_config.hpp"
#include "client_stats.hpp"
#include "decoder.hpp"
#include "frame_records.hpp"
#include "message_types.hpp"
#include "verify_message.hpp"

namespace ocean::client {

// What the session asks of its owner. Every member may be empty (the output is then dropped).
struct ClientSessionEvents {
  std::function<void(std::span<const std::uint8_t>)> send_tcp;
  std::function<void(std::span<const std::uint8_t>)> send_udp;
  // The Welcome was accepted: open the UDP socket to welcome.udp_port when it is not 0.
  std::function<void(const protocol::Welcome&)> on_welcome;
  // A frame completed: normally the newest, but a late copy of an older one too (ticks may come
  // out of order). Valid during the call only.
  std::function<void(const codec::ReconstructedFrame&, Tick tick)> on_frame;
  std::function<void(const protocol::SceneUpdate&)> on_scene_update;
  // The session ended (Bye, Error before the Welcome, a bad TCP message, idle timeout).
  std::function<void(const std::string& why)> on_closed;
};

class ClientSession {
 public:
  enum class State : std::uint8_t { idle, awaiting_welcome, streaming, closed };
  enum class Path : std::uint8_t { tcp, udp_proving, udp };  // where delta frames come from

  ClientSession(ClientSessionConfig config, ClientSessionEvents events);

  // Sends the Hello (the TCP connection is up).
  void start(double now);
  // bytes: one whole message (a TcpFramer message) / one datagram. Verified before anything reads it.
  void on_tcp_message(std::span<const std::uint8_t> bytes, double now);
  void on_udp_datagram(std::span<const std::uint8_t> bytes, double now);
  // Runs the timers: acks, UdpHello retries and fallback, pings, keyframe requests, idle timeout.
  void update(double now);
  // The earliest time update() has something to do; +infinity when nothing is scheduled.
  double next_due() const;
  // Sends Bye{client_quit} and closes.
  void quit(double now);

  State state() const { return state_; }
  Path path() const { return path_; }
  const ClientStats& stats() const { return stats_; }
  // The smoothed round trip (the handshake's before the first Pong) while delta frames come on
  // the TCP stream (the WebSocket's too); 0 while they come, or may come, as datagrams.
  double stream_rtt_s() const {
    if (path_ != Path::tcp) return 0.0;
    return stats_.rtt_smoothed_s > 0.0 ? stats_.rtt_smoothed_s : stats_.handshake_rtt_s;
  }
  const std::string& close_reason() const { return close_reason_; }
  const std::string& last_error() const { return last_error_; }  // the last Error the server sent
  // The reason the server gave for refusing the Hello, if it did.
  const std::optional<protocol::Reason>& refusal() const { return refusal_; }
  // Valid once streaming: the Welcome, the newest scene announced (a SceneUpdate's scene takes
  // effect at its effective tick, which may still be ahead; the decoder knows them all).
  const std::optional<protocol::Welcome>& welcome() const { return welcome_; }
  const protocol::SceneParams& scene() const { return scene_; }
  const codec::Decoder* decoder() const { return decoder_.get(); }
  const ClientSessionConfig& config() const { return config_; }

 private:
  void handle(const wire::Message& message, wire::Transport transport, double now);
  void handle_welcome(const protocol::Welcome& welcome, double now);
  // A block of frame records (a frames datagram or a FrameData message), oldest first.
  void handle_frames(std::span<const std::uint8_t> block, wire::Transport transport, double now);
  // Returns true when the record completed a frame.
  bool handle_record(const protocol::FrameRecord& record, double now);
  void add_scene(Tick from, std::uint32_t serial, const protocol::SceneParams& scene);
  void handle_pong(const protocol::Pong& pong, wire::Transport transport, double now);
  void reject(const protocol::Verified& result, wire::Transport transport, double now);
  void count_rejection(protocol::Reason reason);
  void send(const protocol::Bytes& bytes, wire::Transport transport);
  void send_ack(double now);
  void send_udp_hello(double now);
  void send_ping(double now, wire::Transport transport);
  // UDP has been silent past its limit: true once a Ping sent on TCP since then was answered
  // (TCP works, so UDP is what fails); sends that Ping when due.
  bool tcp_answers(double now);
  void request_keyframe(wire::KeyframeReason reason, double now);
  void fall_back_to_tcp(double now);
  // On the TCP fallback: runs the rounds of UdpHellos that try UDP again; return_to_udp once one
  // is answered.
  void retry_udp(double now);
  void back_off_udp_retry(double now);
  void return_to_udp(double now);
  bool may_retry_udp() const;
  void close(const std::string& why);
  wire::Transport control_path() const;  // UDP once proven, else TCP
  std::span<const std::uint8_t> aligned(std::span<const std::uint8_t> bytes);

  ClientSessionConfig config_;
  ClientSessionEvents events_;
  State state_ = State::idle;
  Path path_ = Path::tcp;
  ClientStats stats_;
  std::string close_reason_;
  std::string last_error_;
  std::optional<protocol::Reason> refusal_;
  std::optional<protocol::Welcome> welcome_;
  protocol::SceneParams scene_;
  std::unique_ptr<codec::Decoder> decoder_;
  std::size_t max_message_bytes_;
  std::vector<std::uint8_t> scratch_;  // aligned copy of a misaligned input
  std::vector<protocol::FrameRecord> records_;  // scratch of handle_frames

  // Timers (absolute times in the caller's clock, seconds).
  double last_rx_ = 0.0;              // any verified message
  double last_udp_rx_ = 0.0;          // any verified datagram
  double hello_sent_ = 0.0;
  double welcome_at_ = 0.0;
  double udp_proof_started_ = 0.0;
  double next_udp_hello_ = 0.0;
  double udp_retry_delay_s_ = 0.0;    // the wait before the next round; 0 = none failed yet
  double next_udp_retry_ = 0.0;       // when the next round starts (on the TCP fallback)
  double udp_retry_round_end_ = 0.0;  // the round under way ends then; 0 = none
  double udp_since_ = 0.0;            // UDP carries the stream since then
  double next_ack_ = 0.0;
  double next_ping_ = 0.0;
  double last_progress_ = 0.0;        // last completed frame (or the Welcome)
  double last_keyframe_request_ = -1e300;
  bool ack_pending_ = false;          // a frame completed since the last Ack
  std::uint64_t keys_acked_ = 0;      // keyframes_complete when the last key was acked at once
  std::uint32_t ping_seq_ = 0;
  // The TCP Ping that tells a dead UDP path from a stalled server (both silent then).
  struct TcpProbe {
    std::uint32_t seq = 0;  // 0: none out
    double sent_s = 0.0;
    bool answered = false;
  } tcp_probe_;
  codec::ChunkError last_chunk_error_ = codec::ChunkError::ok;
};

std::string_view to_string(ClientSession::State state);
std::string_view to_string(ClientSession::Path path);

}  // namespace ocean::client
