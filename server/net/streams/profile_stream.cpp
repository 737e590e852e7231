#include "profile_stream.hpp"

#include "frame_records.hpp"
#include "message_builders.hpp"
#include "wire_limits.hpp"

#include <chrono>
#include <stdexcept>

namespace ocean::server {

codec::EncoderOptions stream_encoder_options() {
  codec::EncoderOptions options;
  options.max_payload = protocol::kMaxChunkPayloadUdp;
  options.history_ticks = protocol::kMaxBaselineGap + 2;  // the acked baseline plus the tick before a key
  options.key_history_ticks = protocol::kMaxFrameLag;    // a key is a baseline however late it is acked
  options.frame_cache_ticks = 1;  // ProfileStream shares each tick's encodes; older frames are never asked for
  return options;
}

ProfileStream::ProfileStream(const Profile& profile, const codec::StreamConfig& config, std::shared_ptr<BuildQueue> builds)
    : profile_(&profile),
      config_(config),
      tick_step_(config.effective_tick_rate_hz() / config.rate_hz),
      encoder_(std::make_unique<codec::Encoder>(config, stream_encoder_options())),
      builds_(std::move(builds)) {
  if (config.effective_tick_rate_hz() % config.rate_hz != 0)
    throw std::invalid_argument("profile " + std::string(profile.name) + ": the tick rate " +
                                std::to_string(config.effective_tick_rate_hz()) + " Hz is not a multiple of its " +
                                std::to_string(config.rate_hz) + " Hz");
}

void ProfileStream::set_scene(Tick from, std::uint32_t serial, const model::SceneParams& scene) {
  encoder_->set_scene(from, static_cast<std::uint8_t>(serial), scene);
  const codec::StreamConfig config = encoder_->scenes().model_config(scene);
  pending_models_.push_back({from, scene, builds_->submit([config, scene] {
                               return std::make_shared<const codec::SceneModel>(config, scene);
                             })});
}

void ProfileStream::add_truth(Tick tick, const sim::Frame& frame) {
  // Models built ahead go to the encoder; one that failed is built (and its error met) by the
  // encoder itself when needed, as before.
  std::erase_if(pending_models_, [this](PendingModel& p) {
    if (p.model.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    try {
      encoder_->provide_scene_model(p.from, p.scene, p.model.get());
    } catch (const std::exception&) {
    }
    return true;
  });
  encoded_.clear();
  encode_seconds_ = 0.0;
  codec::TruthView truth;
  for (int ch = 0; ch < kChannelCount; ++ch) truth[ch] = frame.*sim::kFrameChannels[ch];
  encoder_->add_truth(tick, truth);
  have_newest_ = true;
  newest_tick_ = tick;
}

protocol::FrameRecord record_of(const codec::Chunk& chunk) {
  return protocol::FrameRecord{chunk.tick, chunk.baseline, chunk.key, chunk.index, chunk.count, chunk.payload};
}

const SharedFrame& ProfileStream::key(Tick tick) {
  const auto found = encoded_.find({tick, codec::StateId{tick, 0}});
  if (found != encoded_.end()) return found->second;
  const auto start = std::chrono::steady_clock::now();
  auto frame = encoder_->encode_key(tick);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return remember(tick, codec::StateId{tick, 0}, std::move(frame), took.count());
}

const SharedFrame& ProfileStream::delta(Tick tick, codec::StateId baseline) {
  const auto found = encoded_.find({tick, baseline});
  if (found != encoded_.end()) return found->second;
  const auto start = std::chrono::steady_clock::now();
  auto frame = encoder_->encode_delta(tick, baseline);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return remember(tick, baseline, std::move(frame), took.count());
}

const SharedFrame& ProfileStream::remember(Tick tick, codec::StateId base,
                                           std::shared_ptr<const codec::EncodedFrame> frame, double seconds) {
  SharedFrame shared;
  for (const codec::Chunk& chunk : frame->chunks) {
    const protocol::FrameRecord record = record_of(chunk);
    const std::span<const protocol::FrameRecord> one(&record, 1);
    auto message = std::make_shared<const protocol::Bytes>(protocol::encode(protocol::FrameData{protocol::encode_frame_block(one)}));
    auto datagram = std::make_shared<const protocol::Bytes>(protocol::frames_datagram(one));
    shared.bytes += message->size();
    shared.datagram_bytes += datagram->size();
    shared.messages.push_back(std::move(message));
    shared.datagrams.push_back(std::move(datagram));
  }
  const auto sent = static_cast<double>(shared.datagram_bytes);
  if (!frame->key) mean_delta_bytes_ = mean_delta_bytes_ == 0.0 ? sent : 0.9 * mean_delta_bytes_ + 0.1 * sent;
  encode_seconds_ += seconds;
  shared.encoded = std::move(frame);
  return encoded_.emplace(std::make_pair(tick, base), std::move(shared)).first->second;
}

}  // namespace ocean::server
