// FramePredictor: advance (across scene changes, CODEC.md 7.5) + synthesize on a copy of a decoder state.
#include "frame_predictor.hpp"


namespace ocean::client {

FramePredictor::FramePredictor(const codec::StreamConfig& config, std::uint32_t max_ticks_ahead)
    : config_(config), max_ticks_ahead_(max_ticks_ahead), model_(config) {}

bool FramePredictor::predict(const codec::Decoder& decoder, Tick tick, codec::ReconstructedFrame& out) {
  // The newest complete tick at or before `tick` (usually simply the newest).
  bool found = false;
  Tick base = 0;
  for (Tick t : decoder.complete_ticks())
    if (t <= tick) found = true, base = t;
  if (!found || tick - base > max_ticks_ahead_) return false;
  if (tick > base && !decoder.scenes().prepare(base, tick, false)) return false;
  state_ = *decoder.state(base);
  // Through the decoder's scenes: a weather change announced ahead is predicted exactly too.
  decoder.scenes().advance(state_, base, tick);
  model_.synthesize(state_.cur, decoder.scenes().at(tick)->scene.choppiness, fields_);
  codec::to_float(fields_, config_, out);
  out.tick = tick;
  out.complete = false;
  return true;
}

}  // namespace ocean::client
