// FramePredictor: the codec's own physics as the client's extrapolator. Advances the newest
// complete decoder state to a later tick and synthesizes that tick's heights and slopes (the
// prediction a delta frame would correct), so a starved FrameTimeline keeps the sea moving.
#pragma once

#include "tick.hpp"

#include <cstdint>

#include "decoder.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"

namespace ocean::client {

class FramePredictor {
 public:
  explicit FramePredictor(const codec::StreamConfig& config, std::uint32_t max_ticks_ahead = 64);

  // out = the frame of `tick` predicted from the newest complete state at or before it, marked
  // incomplete. False when there is none, or it is more than max_ticks_ahead behind.
  bool predict(const codec::Decoder& decoder, Tick tick, codec::ReconstructedFrame& out);

 private:
  codec::StreamConfig config_;
  std::uint32_t max_ticks_ahead_;
  codec::ModalModel model_;
  codec::ModalState state_;     // reused: no allocation once grown
  codec::SampleFields fields_;
};

}  // namespace ocean::client
