// ProfileStream: the one codec::Encoder of an offered profile, fed once per tick with that
// profile's band-limited truth. Encodes each (tick, baseline) at most once and hands every session
// the same bytes (the FrameChunk messages, shared), so the cost per tick follows the number of
// distinct baselines, not the number of clients.
#pragma once

#include "build_queue.hpp"
#include "encoder.hpp"
#include "frame.hpp"
#include "frame_records.hpp"
#include "message_types.hpp"
#include "scene_model.hpp"
#include "shared_bytes.hpp"
#include "profile.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <vector>

namespace ocean::server {

// One encoded frame, ready for any session: the codec's frame and its chunks as wire bytes.
struct SharedFrame {
  std::shared_ptr<const codec::EncodedFrame> encoded;
  std::vector<SharedBytes> messages;   // TCP: one FrameData message per chunk
  std::size_t bytes = 0;               // sum of message sizes
  std::vector<SharedBytes> datagrams;  // UDP: one frames datagram per chunk, each <= kMaxDatagram
  std::size_t datagram_bytes = 0;      // sum of datagram sizes
};

// The record of one chunk of an encoded frame (its payload views the frame's chunk).
protocol::FrameRecord record_of(const codec::Chunk& chunk);

class ProfileStream {
 public:
  // tick_rate_hz: the server's; the profile streams every (tick_rate_hz / rate_hz)-th tick.
  // Throws std::invalid_argument when the codec cannot stream the profile (e.g. choppy).
  // builds: where the models of scenes announced ahead are built (shared by a server's streams).
  ProfileStream(const Profile& profile, const codec::StreamConfig& config, std::shared_ptr<BuildQueue> builds);

  const Profile& profile() const { return *profile_; }
  const codec::StreamConfig& config() const { return config_; }
  // The vessels forcing the stream's wake lattice, as its Welcome tells decoders.
  void set_vessels(std::vector<model::VesselTrack> vessels) { encoder_->set_vessels(std::move(vessels)); }
  // A vessel command's fleet from tick `from` on.
  void set_vessels(std::vector<model::VesselTrack> vessels, Tick from) { encoder_->set_vessels(std::move(vessels), from); }
  std::uint32_t tick_step() const { return tick_step_; }
  bool is_frame_tick(Tick tick) const { return tick % tick_step_ == 0; }

  // A scene announced to the clients (SceneUpdate), in force from tick `from` on. Its scene model
  // is built on a thread of its own meanwhile (the lead gives it a second) and handed to the
  // encoder when done: built at its first frame on the network thread instead, a desktop stream's
  // stalled every viewer's tick by about 100 ms.
  void set_scene(Tick from, std::uint32_t serial, const model::SceneParams& scene);

  // Every tick. Forgets the previous tick's encodings.
  void add_truth(Tick tick, const sim::Frame& frame);
  // Samples the encoder clamped to its 2^20 steps so far (codec::Encoder::add_truth).
  std::uint64_t saturated_samples() const { return encoder_->saturated_samples(); }

  // A key of the newest tick added (the scene model's state plus corrections).
  bool can_key(Tick tick) const { return have_newest_ && newest_tick_ == tick; }
  const SharedFrame& key(Tick tick);
  const SharedFrame& delta(Tick tick, codec::StateId baseline);
  bool has_state(codec::StateId id) const { return encoder_->has_state(id); }
  bool has_encoded(Tick tick, codec::StateId baseline) const { return encoded_.count({tick, baseline}) != 0; }
  const codec::ModalState* state(codec::StateId id) const { return encoder_->state(id); }  // tests compare clients with it
  // Nobody receives the stream: its states (about 1 MB each for desktop) go now, not when they age out.
  bool forget_states() { return encoder_->forget_states(); }

  // Encodes run for the current tick (each a distinct (tick, baseline)), and their total time.
  std::size_t encodes_this_tick() const { return encoded_.size(); }
  double encode_seconds_this_tick() const { return encode_seconds_; }
  // Mean bytes of recent delta frames (0 before the first), for choosing a profile that fits.
  double mean_delta_bytes() const { return mean_delta_bytes_; }

 private:
  const SharedFrame& remember(Tick tick, codec::StateId base, std::shared_ptr<const codec::EncodedFrame> frame,
                              double seconds);

  const Profile* profile_;
  codec::StreamConfig config_;
  std::uint32_t tick_step_;
  std::unique_ptr<codec::Encoder> encoder_;
  std::map<std::pair<Tick, codec::StateId>, SharedFrame> encoded_;  // this tick only
  double encode_seconds_ = 0.0;
  Tick newest_tick_ = 0;
  bool have_newest_ = false;
  double mean_delta_bytes_ = 0.0;
  struct PendingModel {
    Tick from;
    model::SceneParams scene;
    std::future<std::shared_ptr<const codec::SceneModel>> model;
  };
  std::shared_ptr<BuildQueue> builds_;
  std::vector<PendingModel> pending_models_;  // being built; handed over by add_truth when ready
};

// The codec options every stream uses: chunks that fit one UDP datagram as a FrameChunk.
codec::EncoderOptions stream_encoder_options();

}  // namespace ocean::server
