// FrameRecorder: a raw TCP client of one server, built from the protocol builders and readers
// only, that asks for one profile on TCP - a keyframe, then deltas each predicted from the frame
// before - and records every FrameChunk exactly as it arrived. Its messages also pass, as they
// came, through a ClientSession that only listens (as ocean-web-replay does): the hash of each
// decoded frame's heights, the sea the viewer would draw, by tick.
#pragma once

#include <asio/connect.hpp>
#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/write.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client_session.hpp"
#include "height_hash.hpp"
#include "message_builders.hpp"
#include "frame_records.hpp"
#include "message_readers.hpp"
#include "tcp_framer.hpp"
#include "verify_message.hpp"

namespace ocean::replica_test {

// One frame as received: its envelope and every chunk's payload by index.
struct RecordedFrame {
  std::uint8_t profile_id = 0;
  Tick tick = 0;
  Tick baseline = 0;
  bool key = false;
  std::uint16_t count = 0;
  std::map<std::uint16_t, protocol::Bytes> payloads;  // index -> payload bytes
  bool complete() const { return payloads.size() == count; }
};

class FrameRecorder {
 public:
  // Connects at once (blocking); the Hello waits for send_hello(), so a test can time it.
  // `decode`: pass every message through the listening ClientSession too (sea(), heights()); off,
  // the recorder only records (a sanitizer's decode is slow enough to cost a busy test its keys).
  FrameRecorder(asio::io_context& io, const asio::ip::tcp::endpoint& server, std::uint8_t profile_id, bool decode = true)
      : socket_(io), profile_id_(profile_id), decode_(decode), decoder_(decoder_config(), decoder_events(sea_, heights_)) {
    decoder_.start(0.0);
    socket_.connect(server);
    socket_.set_option(asio::ip::tcp::no_delay(true));
    do_read();
  }
  // A read completion already queued still runs after close() (cancel cannot recall it): the
  // shared flag tells it the recorder is gone.
  ~FrameRecorder() { *alive_ = false; }
  FrameRecorder(const FrameRecorder&) = delete;
  FrameRecorder& operator=(const FrameRecorder&) = delete;

  void send_hello() {
    const protocol::Bytes hello =
        protocol::encode(protocol::Hello{profile_id_, 0, wire::Transport::tcp, "replica-test"});
    asio::write(socket_, asio::buffer(hello));
  }

  // Stops recording; what was recorded stays.
  void close() {
    *alive_ = false;
    std::error_code ec;
    socket_.close(ec);
  }

  // Frames by tick, in arrival order of their first chunk.
  const std::map<Tick, RecordedFrame>& frames() const { return frames_; }
  const std::optional<protocol::Welcome>& welcome() const { return welcome_; }
  std::optional<Tick> first_key_tick() const { return first_key_tick_; }
  // hash_heights of each frame the listening ClientSession decoded, by tick, and the heights.
  const std::map<Tick, std::uint64_t>& sea() const { return sea_; }
  const std::map<Tick, std::vector<float>>& heights() const { return heights_; }
  // The scene changes announced since the Welcome, in arrival order.
  const std::vector<protocol::SceneUpdate>& scene_updates() const { return scene_updates_; }
  std::optional<Tick> newest_tick() const {
    return frames_.empty() ? std::nullopt : std::optional<Tick>(frames_.rbegin()->first);
  }
  // Chunks that contradict the frame they belong to (envelope differs, index repeated), and
  // every other refusal: a server of this project sends none.
  const std::vector<std::string>& faults() const { return faults_; }
  bool closed() const { return closed_; }

 private:
  void do_read() {
    socket_.async_read_some(asio::buffer(buffer_), [this, alive = alive_](std::error_code ec, std::size_t n) {
      if (!*alive || ec == asio::error::operation_aborted) return;  // closed or destroyed: touch nothing
      if (ec) {
        closed_ = true;
        return;
      }
      std::span<const std::uint8_t> rest(buffer_.data(), n);
      while (!rest.empty()) {
        const protocol::TcpFramer::Result r = framer_.feed(rest);
        rest = rest.subspan(r.consumed);
        if (r.status == protocol::TcpFramer::Status::bad) {
          faults_.push_back("TCP framing: " + std::string(protocol::to_string(r.reason)));
          closed_ = true;
          return;
        }
        if (r.status == protocol::TcpFramer::Status::need_more) break;
        on_message(framer_.message());
      }
      do_read();
    });
  }

  static client::ClientSessionConfig decoder_config() {
    client::ClientSessionConfig config;
    config.transport = wire::Transport::tcp;
    config.close_on_bad_tcp_message = false;  // a refusal shows as faults() below, not as a closed decoder
    return config;
  }
  static client::ClientSessionEvents decoder_events(std::map<Tick, std::uint64_t>& sea,
                                                   std::map<Tick, std::vector<float>>& heights) {
    client::ClientSessionEvents events;
    events.on_frame = [&sea, &heights](const codec::ReconstructedFrame& frame, Tick tick) {
      sea.emplace(tick, client::hash_heights(frame.height));
      heights.emplace(tick, frame.height);
    };
    return events;
  }

  void on_message(std::span<const std::uint8_t> bytes) {
    if (decode_) decoder_.on_tcp_message(bytes, 0.0);
    const std::size_t limit = welcome_ ? welcome_->max_message_bytes : protocol::kDefaultMaxMessageBytes;
    const protocol::Verified v = protocol::verify_message(bytes, {protocol::Sender::server, wire::Transport::tcp, limit});
    if (!v) {
      faults_.push_back("refused message: " + protocol::describe(v));
      return;
    }
    const protocol::AnyMessage message = protocol::decode(*v.message);
    if (const auto* w = std::get_if<protocol::Welcome>(&message)) {
      welcome_ = *w;
      framer_.set_max_message_bytes(w->max_message_bytes);
    } else if (const auto* data = std::get_if<protocol::FrameData>(&message)) {
      std::vector<protocol::FrameRecord> records;
      if (const protocol::FrameBlockResult r = protocol::decode_frame_block(data->frames, records); !r)
        faults_.push_back("refused FrameData: " + r.rule);
      for (const protocol::FrameRecord& record : records) this->record(record);
    } else if (const auto* update = std::get_if<protocol::SceneUpdate>(&message)) {
      scene_updates_.push_back(*update);
    } else if (const auto* e = std::get_if<protocol::Error>(&message)) {
      faults_.push_back("Error: " + e->text);
    }
  }

  void record(const protocol::FrameRecord& c) {
    auto [it, fresh] = frames_.try_emplace(c.tick);
    RecordedFrame& f = it->second;
    if (fresh) {
      f = RecordedFrame{profile_id_, c.tick, c.baseline, c.key, c.count, {}};
      if (c.key && !first_key_tick_) first_key_tick_ = c.tick;
    } else if (f.baseline != c.baseline || f.key != c.key || f.count != c.count) {
      faults_.push_back("tick " + std::to_string(c.tick) + ": chunk envelope differs from its frame's");
      return;
    }
    if (!f.payloads.emplace(c.index, protocol::Bytes(c.payload.begin(), c.payload.end())).second)
      faults_.push_back("tick " + std::to_string(c.tick) + ": chunk " + std::to_string(c.index) + " twice");
  }

  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
  asio::ip::tcp::socket socket_;
  std::uint8_t profile_id_;
  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 16384> buffer_{};
  std::optional<protocol::Welcome> welcome_;
  std::map<Tick, RecordedFrame> frames_;
  std::optional<Tick> first_key_tick_;
  std::vector<protocol::SceneUpdate> scene_updates_;
  bool decode_;
  std::map<Tick, std::uint64_t> sea_;  // before decoder_, which writes them
  std::map<Tick, std::vector<float>> heights_;
  client::ClientSession decoder_;
  std::vector<std::string> faults_;
  bool closed_ = false;
};

}  // namespace ocean::replica_test
