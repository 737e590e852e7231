// ProfileStream: the one codec::Encoder of an offered profile, fed once per tick with that
// profile's band-limited truth. Encodes each (tick, baseline) at most once and hands every session
// the same bytes (the FrameChunk messages, shared), so the cost per tick follows the number of
// distinct baselines, not the number of clients.
#pragma once

#include "encoder.hpp"
#include "frame.hpp"
#include "message_types.hpp"
#include "profile.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace ocean::server {

using SharedBytes = std::shared_ptr<const protocol::Bytes>;

// One encoded frame, ready for any session: the codec's frame and its chunks as wire messages.
struct SharedFrame {
  std::shared_ptr<const codec::EncodedFrame> encoded;
  std::vector<SharedBytes> messages;  // one FrameChunk message per chunk, each <= kMaxDatagram
  std::size_t bytes = 0;              // sum of message sizes
};

class ProfileStream {
 public:
  // tick_rate_hz: the server's; the profile streams every (tick_rate_hz / rate_hz)-th tick.
  // Throws std::invalid_argument when the codec cannot stream the profile (e.g. choppy).
  ProfileStream(const Profile& profile, const codec::StreamConfig& config);

  const Profile& profile() const { return *profile_; }
  const codec::StreamConfig& config() const { return config_; }
  std::uint32_t tick_step() const { return tick_step_; }
  bool is_frame_tick(std::uint32_t tick) const { return tick % tick_step_ == 0; }

  // Every tick (a key's velocity needs the tick before it). Forgets the previous tick's encodings.
  void add_truth(std::uint32_t tick, const sim::Frame& frame);
  // A new scene: the codec cannot predict across a physics change; drop every state.
  void reset(const codec::StreamConfig& config);

  // A key needs the truth of the tick before it too (its velocity), in the same scene.
  bool can_key(std::uint32_t tick) const { return have_previous_ && previous_tick_ + 1 == tick; }
  const SharedFrame& key(std::uint32_t tick);
  const SharedFrame& delta(std::uint32_t tick, codec::StateId baseline);
  bool has_state(codec::StateId id) const { return encoder_->has_state(id); }

  // Encodes run for the current tick (each a distinct (tick, baseline)), and their total time.
  std::size_t encodes_this_tick() const { return encoded_.size(); }
  double encode_seconds_this_tick() const { return encode_seconds_; }
  // Mean bytes of recent delta frames (0 before the first), for choosing a profile that fits.
  double mean_delta_bytes() const { return mean_delta_bytes_; }

 private:
  const SharedFrame& remember(std::uint32_t tick, codec::StateId base,
                              std::shared_ptr<const codec::EncodedFrame> frame, double seconds);

  const Profile* profile_;
  codec::StreamConfig config_;
  std::uint32_t tick_step_;
  std::unique_ptr<codec::Encoder> encoder_;
  std::map<std::pair<std::uint32_t, codec::StateId>, SharedFrame> encoded_;  // this tick only
  double encode_seconds_ = 0.0;
  std::uint32_t previous_tick_ = 0, newest_tick_ = 0;  // the last two ticks added since a reset
  bool have_previous_ = false, have_newest_ = false;
  double mean_delta_bytes_ = 0.0;
};

// The codec options every stream uses: chunks that fit one UDP datagram as a FrameChunk.
codec::EncoderOptions stream_encoder_options();

}  // namespace ocean::server
