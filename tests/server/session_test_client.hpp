// SessionTestClient: a small blocking client for in-process server tests, built from the protocol
// builders and codec::Decoder only: handshake, UDP proof, frame decoding, acks, and a record of
// every completed tick's reconstruction. The test thread pumps it; nothing here runs by itself.
#pragma once

#include "ack_window.hpp"
#include "decoder.hpp"
#include "frame_records.hpp"
#include "stream_wire.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "tcp_framer.hpp"
#include "verify_message.hpp"
#include "websocket_test_frames.hpp"

#include <asio/connect.hpp>
#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/ip/udp.hpp>
#include <asio/read.hpp>
#include <asio/write.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace ocean::server::test {

namespace proto = ocean::protocol;

class SessionTestClient {
 public:
  // websocket_origin: connect to a WebSocket port (tcp_port) instead, sending this Origin ("" =
  // none); the upgrade's HTTP status is in ws_status.
  SessionTestClient(std::uint16_t tcp_port, std::uint16_t udp_port, int receive_buffer_bytes = 0,
                    std::optional<std::string> websocket_origin = std::nullopt)
      : tcp_(context_), udp_(context_), udp_port_(udp_port), websocket_(websocket_origin.has_value()) {
    tcp_.open(asio::ip::tcp::v4());
    if (receive_buffer_bytes > 0) tcp_.set_option(asio::socket_base::receive_buffer_size(receive_buffer_bytes));
    tcp_.connect({asio::ip::make_address("127.0.0.1"), tcp_port});
    tcp_.set_option(asio::ip::tcp::no_delay(true));  // as the client library's: no Nagle wait on small requests
    if (websocket_) upgrade(tcp_port, *websocket_origin);
    tcp_.non_blocking(true);
    udp_.open(asio::ip::udp::v4());
    udp_.bind({asio::ip::make_address("127.0.0.1"), 0});
    udp_.non_blocking(true);
  }

  void send_tcp(const proto::Bytes& bytes) {
    if (websocket_) return send_raw(::ocean::test::ws_client_frame(::ocean::test::ws_binary, bytes));
    send_raw(bytes);
  }
  void send_raw(std::span<const std::uint8_t> bytes) {
    tcp_.non_blocking(false);
    std::error_code error;
    asio::write(tcp_, asio::buffer(bytes.data(), bytes.size()), error);
    if (error) send_failed_ = true;
    tcp_.non_blocking(true);
  }
  bool send_failed() const { return send_failed_; }  // the server closed (or reset) the connection
  void send_udp(const proto::Bytes& bytes) {
    std::error_code error;
    udp_.send_to(asio::buffer(bytes), {asio::ip::make_address("127.0.0.1"), udp_port_}, 0, error);
  }
  void hello(const proto::Hello& hello) { send_tcp(proto::encode(hello)); }

  // Reads what arrived (TCP and UDP) without blocking; false once TCP is closed. Each socket for
  // about 20 ms a call at most: a client that decodes slower than the server sends (a sanitizer
  // build on a busy machine) would otherwise never return to its caller's condition.
  bool pump() {
    if (reading_paused) return !tcp_closed_;
    std::array<std::uint8_t, 8192> buffer;
    const auto tcp_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(20);
    while (!tcp_closed_ && std::chrono::steady_clock::now() < tcp_until) {
      std::error_code error;
      const std::size_t n = tcp_.read_some(asio::buffer(buffer), error);
      if (error == asio::error::would_block) break;
      if (error || n == 0) {
        tcp_closed_ = true;
        break;
      }
      std::span<const std::uint8_t> bytes(buffer.data(), n);
      if (websocket_) {
        on_websocket_bytes(bytes);
        continue;
      }
      while (!bytes.empty()) {
        const auto result = framer_.feed(bytes);
        bytes = bytes.subspan(result.consumed);
        if (result.status == proto::TcpFramer::Status::bad) {
          tcp_closed_ = true;
          break;
        }
        if (result.status == proto::TcpFramer::Status::good) on_message(framer_.message(), wire::Transport::tcp);
      }
    }
    const auto udp_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(20);
    while (std::chrono::steady_clock::now() < udp_until) {
      alignas(8) std::array<std::uint8_t, 2048> datagram;
      asio::ip::udp::endpoint from;
      std::error_code error;
      const std::size_t n = udp_.receive_from(asio::buffer(datagram), from, 0, error);
      if (error) break;
      udp_bytes_in += n;
      if (drop_udp_every && ++udp_datagrams_seen % drop_udp_every == 0) continue;  // a lossy link
      if (n == 0) continue;
      if (datagram[0] == static_cast<std::uint8_t>(proto::DatagramKind::frames)) {
        on_frames({datagram.data() + 1, n - 1}, wire::Transport::udp);
      } else {
        alignas(8) std::array<std::uint8_t, 2048> message;
        std::copy(datagram.begin() + 1, datagram.begin() + static_cast<std::ptrdiff_t>(n), message.begin());
        on_message({message.data(), n - 1}, wire::Transport::udp);
      }
    }
    return !tcp_closed_;
  }

  // Sends UdpHello every 250 ms from inside pump loops until UdpReady came.
  void prove_udp_if_due() {
    if (!welcome || welcome->udp_port == 0 || udp_ready) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_udp_hello_ < std::chrono::milliseconds(250)) return;
    last_udp_hello_ = now;
    send_udp(proto::encode(proto::UdpHello{welcome->session_id, welcome->udp_cookie}));
  }

  // Every complete tick's reconstruction, as the decoder showed it when it completed.
  std::map<Tick, std::vector<float>> completed_heights;
  bool keep_frames = false;  // then every channel too
  std::map<Tick, codec::ReconstructedFrame> completed_frames;
  const codec::StreamConfig& stream_config() const { return config_; }
  std::vector<proto::HeightAnswer> height_answers;
  std::optional<proto::Welcome> welcome;
  std::vector<proto::Error> errors;
  std::vector<proto::Bye> byes;
  std::vector<proto::SceneUpdate> scene_updates;
  std::vector<Tick> key_ticks;
  bool udp_ready = false;
  bool reading_paused = false;
  bool send_acks = true;
  std::size_t drop_udp_every = 0;  // > 0: every n-th datagram is dropped unread
  std::size_t udp_datagrams_seen = 0;
  std::string first_rejection, last_rejection;  // the decoder's reasons for chunks it refused
  std::size_t udp_frame_chunks = 0, tcp_frame_chunks = 0, udp_bytes_in = 0, rejected_chunks = 0, udp_bundles = 0;
  bool closed() const { return tcp_closed_; }
  // What the stream has done so far, for a failed wait's message.
  std::string progress() const {
    std::ostringstream out;
    out << "welcome " << (welcome ? "yes" : "no") << ", udp_ready " << udp_ready << ", chunks tcp " << tcp_frame_chunks
        << " udp " << udp_frame_chunks << " rejected " << rejected_chunks << " (first: " << first_rejection
        << "; last: " << last_rejection << "), keyframes " << key_ticks.size()
        << ", completed " << completed_heights.size();
    if (decoder_) out << " (decoder complete " << decoder_->complete_ticks().size() << ")";
    out << ", errors " << errors.size() << ", closed " << tcp_closed_;
    return out.str();
  }
  int ws_status = 0;                      // the WebSocket upgrade's HTTP status
  std::optional<std::uint16_t> ws_close_code;  // the server's close frame

 private:
  void on_message(std::span<const std::uint8_t> bytes, wire::Transport transport) {
    const proto::Verified verified = proto::verify_message(
        bytes, {proto::Sender::server, transport, welcome ? welcome->max_message_bytes : proto::kDefaultMaxMessageBytes});
    if (!verified) {
      ++rejected_chunks;
      return;
    }
    const proto::AnyMessage message = proto::decode(*verified.message);
    if (const auto* w = std::get_if<proto::Welcome>(&message)) {
      welcome = *w;
      framer_.set_max_message_bytes(w->max_message_bytes);
      config_ = codec::decoder_config(*w);
      codec::DecoderOptions options;
      options.max_payload = proto::kMaxChunkPayloadUdp;
      // As ClientSession keeps them: a server may base a delta on any acked frame this old
      // (PROTOCOL.md 7), as a busy one does when it rebases to a state it has encoded already.
      options.history_ticks = proto::kMaxBaselineGap;
      decoder_ = std::make_unique<codec::Decoder>(config_, options);
      decoder_->add_scene(0, static_cast<std::uint8_t>(w->scene_serial), w->scene);
      if (config_.has_wake()) decoder_->set_vessels(w->vessels);
    } else if (const auto* data = std::get_if<proto::FrameData>(&message)) {
      on_frames(data->frames, transport);
    } else if (std::get_if<proto::UdpReady>(&message)) {
      udp_ready = true;
    } else if (const auto* e = std::get_if<proto::Error>(&message)) {
      errors.push_back(*e);
    } else if (const auto* b = std::get_if<proto::Bye>(&message)) {
      byes.push_back(*b);
    } else if (const auto* u = std::get_if<proto::SceneUpdate>(&message)) {
      scene_updates.push_back(*u);
      if (decoder_)  // the stream goes on: the decoder switches scene at the update's tick
        decoder_->add_scene(u->effective_tick, static_cast<std::uint8_t>(u->serial), u->scene);
      if (decoder_ && u->vessels && config_.has_wake()) decoder_->set_vessels(*u->vessels, u->effective_tick);
    } else if (const auto* a = std::get_if<proto::HeightAnswer>(&message)) {
      height_answers.push_back(*a);
    }
  }

  // A block of frame records: a FrameData message, or a frames datagram (several = a bundle).
  void on_frames(std::span<const std::uint8_t> block, wire::Transport transport) {
    std::vector<proto::FrameRecord> records;
    if (!proto::decode_frame_block(block, records)) {
      ++rejected_chunks;
      return;
    }
    if (records.size() > 1) ++udp_bundles;
    for (const proto::FrameRecord& r : records)
      if (!decoder_ || !decoder_->is_complete(r.tick)) on_record(r, transport);
  }

  void on_record(const proto::FrameRecord& record, wire::Transport transport) {
    (transport == wire::Transport::udp ? udp_frame_chunks : tcp_frame_chunks)++;
    if (!decoder_) return;
    const codec::ChunkView view{record.tick, record.baseline, record.key, record.index, record.count, record.payload};
    if (const codec::ChunkError error = decoder_->accept(view); error != codec::ChunkError::ok) {
      ++rejected_chunks;
      const std::string why = std::string(codec::to_string(error)) + " (tick " + std::to_string(record.tick) + " on " +
                              std::to_string(record.baseline) + ", newest complete " +
                              std::to_string(decoder_->newest_complete().value_or(0)) + ")";
      if (first_rejection.empty()) first_rejection = why;
      last_rejection = why;
      return;
    }
    const Tick tick = record.tick;
    if (!decoder_->is_complete(tick) || completed_heights.count(tick)) return;
    if (record.key) key_ticks.push_back(tick);
    const codec::ReconstructedFrame* shown = decoder_->latest();
    if (shown && shown->tick == tick && shown->complete) {
      completed_heights[tick] = shown->height;
      if (keep_frames) completed_frames[tick] = *shown;
    }
    const std::vector<Tick> ticks = decoder_->complete_ticks();
    const auto window = proto::ack_window(ticks);
    if (!window || !welcome || !send_acks) return;
    const proto::Ack ack{welcome->session_id, welcome->udp_cookie, window->latest_tick, window->bits};
    if (udp_ready) send_udp(proto::encode(ack));
    else send_tcp(proto::encode(ack));
  }

  void upgrade(std::uint16_t port, const std::string& origin) {
    const std::string request = ::ocean::test::ws_upgrade_request(port, origin);
    asio::write(tcp_, asio::buffer(request));
    std::string response;
    std::array<char, 1024> chunk;
    while (response.find("\r\n\r\n") == std::string::npos) {
      std::error_code error;
      const std::size_t n = tcp_.read_some(asio::buffer(chunk), error);
      if (error || n == 0) break;
      response.append(chunk.data(), n);
    }
    if (response.rfind("HTTP/1.1 ", 0) == 0) ws_status = std::atoi(response.c_str() + 9);
    const std::size_t end = response.find("\r\n\r\n");
    if (end != std::string::npos && end + 4 < response.size())
      deframer_.feed(std::span(reinterpret_cast<const std::uint8_t*>(response.data()) + end + 4, response.size() - end - 4));
  }

  void on_websocket_bytes(std::span<const std::uint8_t> bytes) {
    deframer_.feed(bytes);
    while (auto frame = deframer_.next()) {
      if (frame->opcode == ::ocean::test::ws_close) {
        if (frame->payload.size() >= 2) ws_close_code = static_cast<std::uint16_t>(frame->payload[0] << 8 | frame->payload[1]);
        continue;
      }
      if (frame->opcode != ::ocean::test::ws_binary) continue;
      aligned_.assign((frame->payload.size() + 7) / 8, 0);  // verify_message needs 8-byte alignment
      std::memcpy(aligned_.data(), frame->payload.data(), frame->payload.size());
      on_message(std::span(reinterpret_cast<const std::uint8_t*>(aligned_.data()), frame->payload.size()), wire::Transport::tcp);
    }
  }

  asio::io_context context_;
  asio::ip::tcp::socket tcp_;
  asio::ip::udp::socket udp_;
  std::uint16_t udp_port_;
  proto::TcpFramer framer_;
  bool tcp_closed_ = false;
  codec::StreamConfig config_;
  std::unique_ptr<codec::Decoder> decoder_;
  std::chrono::steady_clock::time_point last_udp_hello_{};
  bool websocket_ = false;
  bool send_failed_ = false;
  ::ocean::test::WsDeframer deframer_;
  std::vector<std::uint64_t> aligned_;
};

}  // namespace ocean::server::test
