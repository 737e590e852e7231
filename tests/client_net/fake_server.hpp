// FakeServer: the server side of PROTOCOL.md in a few lines, for tests only. Pure (time is an
// argument, output goes to outboxes): Hello -> Welcome + keyframe on TCP, UdpHello -> UdpReady,
// one frame per step(), deltas predicted from the newest acked tick (UDP) or the last TCP frame.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "ack_window.hpp"
#include "encoder.hpp"
#include "frame_records.hpp"
#include "stream_wire.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "profile.hpp"
#include "verify_message.hpp"
#include "wave_truth.hpp"

namespace ocean::client::test {

struct FakeServerOptions {
  std::uint8_t profile_id = 1;       // mobile: 64 x 64, 30 Hz
  bool offer_udp = true;
  bool answer_udp_hello = true;      // false: the UDP path is black-holed
  bool trust_acks = true;            // false: UDP deltas predicted from the last frame sent (a broken server)
  double noise_m = 0.0;              // truth noise: > 0 forces corrections, so deltas of several chunks
  std::size_t max_payload = codec::kDefaultMaxPayload;
  bool broken_stream_params = false;  // the Welcome names a stream no decoder accepts (a broken server)
};

class FakeServer {
 public:
  static constexpr std::uint64_t kSessionId = 0x1122334455667788ull;

  explicit FakeServer(FakeServerOptions options = {})
      : options_(options),
        profile_(*find_profile(options.profile_id)),
        config_(codec_config(profile_)),
        encoder_(config_, encoder_options(options)),
        truth_(profile_.grid, 64.0, options.noise_m) {
    period_ = 1.0 / profile_.rate_hz;
    truth_.at(0, period_);
    encoder_.set_scene(0, 0, welcome().scene);
    encoder_.add_truth(0, truth_.view());
  }

  const codec::StreamConfig& config() const { return config_; }
  double tick_period_s() const { return period_; }
  Tick tick() const { return tick_; }
  bool udp_ready() const { return udp_ready_; }

  protocol::Welcome welcome() const {
    protocol::Welcome w;
    w.session_id = kSessionId;
    w.stream = codec::wire_stream(codec::StreamConfig::from_profile(profile_, 64.0, 64.0, 9.81, 0.0));  // choppy as the profile says
    if (options_.broken_stream_params) w.stream.height_step_m = 0.0f;
    w.scene.size_x = w.scene.size_z = std::max<std::uint16_t>(64, profile_.grid);
    w.scene.patch_x_m = w.scene.patch_z_m = 64.0;
    w.scene.wind_speed_mps = 10.0;
    w.scene.fetch_m = 100000.0;
    w.scene.amplitude = 1.0;
    w.scene.gravity_mps2 = 9.81;
    w.scene.seed = 1;
    w.offered_profiles = {profile_.id};
    w.current_tick = tick_;
    w.tick_period_s = period_;
    if (options_.offer_udp) {
      w.udp_port = 40000;
      w.udp_cookie = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    }
    w.max_message_bytes = static_cast<std::uint32_t>(protocol::kDefaultMaxMessageBytes);
    return w;
  }

  // Client -> server. Bad input is counted and dropped (the client is under test, not us).
  void on_tcp(std::span<const std::uint8_t> bytes, double now) { on_message(bytes, wire::Transport::tcp, now); }
  void on_udp(std::span<const std::uint8_t> bytes, double now) { on_message(bytes, wire::Transport::udp, now); }

  // Advances one tick and sends its frame (if a session is up).
  void step(double = 0.0) {
    ++tick_;
    truth_.at(tick_, period_);
    encoder_.add_truth(tick_, truth_.view());
    if (!welcomed_) return;
    const bool via_udp = udp_ready_ && !key_needed_;
    std::shared_ptr<const codec::EncodedFrame> frame;
    bool tcp_until_acked = false;  // as ocean-server: UDP deltas only from an acked baseline
    if (!key_needed_) {
      std::optional<Tick> base;
      if (via_udp && options_.trust_acks) {
        if (acked_ && tick_ - acked_->latest_tick <= protocol::kMaxBaselineGap) {
          base = acked_->latest_tick;
        } else if (!acked_ && tick_ - last_tcp_ <= protocol::kMaxBaselineGap) {
          base = last_tcp_;
          tcp_until_acked = true;
        }
      } else if (last_sent_ && tick_ - *last_sent_ <= protocol::kMaxBaselineGap) {
        base = via_udp ? *last_sent_ : last_tcp_;
      }
      if (base && sent_.count(*base) && encoder_.has_state(sent_[*base])) frame = encoder_.encode_delta(tick_, sent_[*base]);
    }
    if (!frame) frame = encoder_.encode_key(tick_);
    key_needed_ = false;
    sent_[tick_] = frame->id;
    frames_[tick_] = frame;
    last_sent_ = tick_;
    const bool udp = udp_ready_ && !frame->key && !tcp_until_acked;
    if (!udp) last_tcp_ = tick_;
    if (frame->key) ++keyframes_sent;
    for (const codec::Chunk& c : frame->chunks) {
      const protocol::FrameRecord record{c.tick, c.baseline, c.key, c.index, c.count, c.payload};
      const std::span<const protocol::FrameRecord> one(&record, 1);
      if (udp)
        to_client_udp.push_back(protocol::frames_datagram(one));
      else
        to_client_tcp.push_back(protocol::encode(protocol::FrameData{protocol::encode_frame_block(one)}));
    }
  }

  // What the encoder says the client shows for tick once complete (null if never sent).
  const codec::EncodedFrame* sent_frame(Tick tick) const {
    auto it = frames_.find(tick);
    return it == frames_.end() ? nullptr : it->second.get();
  }
  const codec::ModalState* sent_state(Tick tick) const {
    auto it = sent_.find(tick);
    return it == sent_.end() ? nullptr : encoder_.state(it->second);
  }

  std::vector<protocol::Bytes> to_client_tcp, to_client_udp;
  std::vector<protocol::Ack> acks;
  std::vector<wire::KeyframeReason> keyframe_requests;
  int udp_hellos = 0, set_transport_tcp = 0, keyframes_sent = 0, rejected = 0, pings = 0;

 private:
  // Its truth has heights and slopes only, so it encodes without choppy channels whatever the
  // profile (the Welcome still says what the profile says).
  static codec::StreamConfig codec_config(const Profile& profile) {
    codec::StreamConfig c = codec::StreamConfig::from_profile(profile, 64.0, 64.0, 9.81, 0.0);
    c.choppy = false;
    return c;
  }

  static codec::EncoderOptions encoder_options(const FakeServerOptions& o) {
    codec::EncoderOptions e;
    e.max_payload = o.max_payload;
    return e;
  }

  void on_message(std::span<const std::uint8_t> bytes, wire::Transport transport, double now) {
    protocol::Bytes copy(bytes.begin(), bytes.end());  // aligned
    const auto v = protocol::verify_message(copy, {protocol::Sender::client, transport, protocol::kDefaultMaxMessageBytes});
    if (!v) {
      ++rejected;
      return;
    }
    if (transport == wire::Transport::udp && v.message->body_type() != wire::Body::UdpHello &&
        protocol::check_udp_sender(*v.message, kSessionId, welcome().udp_cookie) != protocol::Reason::ok) {
      ++rejected;
      return;
    }
    const protocol::AnyMessage m = protocol::decode(*v.message);
    if (std::holds_alternative<protocol::Hello>(m)) {
      welcomed_ = true;
      key_needed_ = true;
      to_client_tcp.push_back(protocol::encode(welcome()));
    } else if (std::holds_alternative<protocol::UdpHello>(m)) {
      ++udp_hellos;
      if (options_.answer_udp_hello && options_.offer_udp) {
        udp_ready_ = true;
        to_client_udp.push_back(protocol::message_datagram(protocol::encode(protocol::UdpReady{kSessionId})));
      }
    } else if (auto* ack = std::get_if<protocol::Ack>(&m)) {
      acks.push_back(*ack);
      const protocol::AckWindow w{ack->latest_tick, ack->ack_bits};
      if (!acked_ || w.latest_tick >= acked_->latest_tick) acked_ = w;
    } else if (auto* request = std::get_if<protocol::KeyframeRequest>(&m)) {
      keyframe_requests.push_back(request->reason);
      key_needed_ = true;
    } else if (auto* set = std::get_if<protocol::SetTransport>(&m)) {
      if (set->transport == wire::Transport::tcp) {
        ++set_transport_tcp;
        udp_ready_ = false;
        key_needed_ = true;
      }
    } else if (auto* ping = std::get_if<protocol::Ping>(&m)) {
      ++pings;
      protocol::Pong pong{ping->seq, ping->client_time_us, tick_, static_cast<std::int64_t>(now * 1000)};
      if (transport == wire::Transport::udp)
        to_client_udp.push_back(protocol::message_datagram(protocol::encode(pong)));
      else
        to_client_tcp.push_back(protocol::encode(pong));
    }
  }

  FakeServerOptions options_;
  Profile profile_;
  codec::StreamConfig config_;
  codec::Encoder encoder_;
  WaveTruth truth_;
  double period_ = 1.0 / 30.0;
  Tick tick_ = 0;
  bool welcomed_ = false, udp_ready_ = false, key_needed_ = false;
  std::optional<protocol::AckWindow> acked_;
  std::optional<Tick> last_sent_;
  Tick last_tcp_ = 0;
  std::map<Tick, codec::StateId> sent_;
  std::map<Tick, std::shared_ptr<const codec::EncodedFrame>> frames_;
};

}  // namespace ocean::client::test
