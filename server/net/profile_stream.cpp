#include "profile_stream.hpp"

#include "message_builders.hpp"
#include "wire_limits.hpp"

#include <chrono>
#include <stdexcept>

namespace ocean::server {

codec::EncoderOptions stream_encoder_options() {
  codec::EncoderOptions options;
  options.max_payload = protocol::kMaxChunkPayloadUdp;
  options.history_ticks = protocol::kMaxBaselineGap + 2;  // the acked baseline plus the tick before a key
  return options;
}

ProfileStream::ProfileStream(const Profile& profile, const codec::StreamConfig& config)
    : profile_(&profile),
      config_(config),
      tick_step_(config.effective_tick_rate_hz() / config.rate_hz),
      encoder_(std::make_unique<codec::Encoder>(config, stream_encoder_options())) {
  if (config.effective_tick_rate_hz() % config.rate_hz != 0)
    throw std::invalid_argument("profile " + std::string(profile.name) + ": the tick rate " +
                                std::to_string(config.effective_tick_rate_hz()) + " Hz is not a multiple of its " +
                                std::to_string(config.rate_hz) + " Hz");
}

void ProfileStream::add_truth(std::uint32_t tick, const sim::Frame& frame) {
  encoded_.clear();
  encode_seconds_ = 0.0;
  encoder_->add_truth(tick, codec::TruthView{frame.height, frame.slope_x, frame.slope_z});
  have_previous_ = have_newest_;
  previous_tick_ = newest_tick_;
  have_newest_ = true;
  newest_tick_ = tick;
}

void ProfileStream::reset(const codec::StreamConfig& config) {
  config_ = config;
  encoder_ = std::make_unique<codec::Encoder>(config, stream_encoder_options());
  encoded_.clear();
  have_previous_ = have_newest_ = false;
}

const SharedFrame& ProfileStream::key(std::uint32_t tick) {
  const auto found = encoded_.find({tick, codec::StateId{tick, 0}});
  if (found != encoded_.end()) return found->second;
  const auto start = std::chrono::steady_clock::now();
  auto frame = encoder_->encode_key(tick);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return remember(tick, codec::StateId{tick, 0}, std::move(frame), took.count());
}

const SharedFrame& ProfileStream::delta(std::uint32_t tick, codec::StateId baseline) {
  const auto found = encoded_.find({tick, baseline});
  if (found != encoded_.end()) return found->second;
  const auto start = std::chrono::steady_clock::now();
  auto frame = encoder_->encode_delta(tick, baseline);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return remember(tick, baseline, std::move(frame), took.count());
}

const SharedFrame& ProfileStream::remember(std::uint32_t tick, codec::StateId base,
                                           std::shared_ptr<const codec::EncodedFrame> frame, double seconds) {
  SharedFrame shared;
  const protocol::FrameHeader header{tick, frame->key ? tick : frame->base.tick, frame->key, profile_->id};
  for (const codec::Chunk& chunk : frame->chunks) {
    auto bytes = std::make_shared<const protocol::Bytes>(
        protocol::encode(protocol::FrameChunk{header, chunk.index, chunk.count, chunk.payload}));
    shared.bytes += bytes->size();
    shared.messages.push_back(std::move(bytes));
  }
  if (!frame->key) mean_delta_bytes_ = mean_delta_bytes_ == 0.0 ? static_cast<double>(shared.bytes)
                                                                : 0.9 * mean_delta_bytes_ + 0.1 * static_cast<double>(shared.bytes);
  encode_seconds_ += seconds;
  shared.encoded = std::move(frame);
  return encoded_.emplace(std::make_pair(tick, base), std::move(shared)).first->second;
}

}  // namespace ocean::server
