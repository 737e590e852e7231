// Decoder: the client side of a stream. Accepts chunks in any order, refuses malformed ones with
// a reason (leaving its state untouched), shows the newest frame (rows of missing chunks keep the
// prediction) and keeps the states of complete frames as baselines for later deltas.
#pragma once

#include "chunk_body.hpp"
#include "decode_memo.hpp"
#include "chunk_format.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace ocean::codec {

struct DecoderOptions {
  std::size_t max_payload = kDefaultMaxPayload;  // larger payloads are refused as oversized
  std::uint32_t history_ticks = 32;  // complete states older than newest complete - this are dropped
  std::uint32_t max_lag = 64;        // largest tick - baseline accepted (the advance costs lag steps)
  std::size_t max_pending = 8;       // incomplete frames kept; the oldest is dropped beyond this
  DecodeMemo* memo = nullptr;        // shared with other decoders of the same stream (same thread)
};

class Decoder {
 public:
  // Throws invalid_argument on bad options or a memo of another stream configuration.
  explicit Decoder(const StreamConfig& config, DecoderOptions options = {});

  const StreamConfig& config() const { return config_; }

  // Takes one chunk; on any error nothing inside the decoder changes.
  ChunkError accept(const ChunkView& chunk);
  ChunkError accept(const Chunk& chunk) { return accept(view(chunk)); }

  // The newest frame that has anything to show (a complete key, or a delta with at least one
  // chunk); nullptr before the first key completes. Valid until the next accept().
  const ReconstructedFrame* latest();

  // The frame the last accept() completed, also when a newer frame is already on show (a copy
  // that arrived late, which a jitter buffer can still use); nullptr when that accept completed
  // none. Valid until the next accept().
  const ReconstructedFrame* just_completed();

  bool is_complete(std::uint32_t tick) const { return states_.count(tick) != 0; }
  std::optional<std::uint32_t> newest_complete() const;
  std::vector<std::uint32_t> complete_ticks() const;  // ascending; what the client may ack
  const ModalState* state(std::uint32_t tick) const;

 private:
  struct Pending {
    std::uint32_t baseline = 0;
    bool key = false;
    std::uint16_t count = 0;
    std::vector<bool> got;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    std::uint16_t received = 0;
    ModalState predicted;                  // delta: advanced baseline state
    SampleFields fields;                   // delta: prediction + corrections received so far
    std::vector<KeyCoefficient> key_coefficients;  // key: filled as chunks arrive
    std::uint8_t pos_shift = 0, vel_shift = 0;
    Corrections corrections;
    DecodeMemo::Payloads key_payloads;  // with a memo: the key's chunks by index, to look it up whole
  };

  ChunkError check(const ChunkView& c, const ChunkHeader& h, const BodyLayout& layout) const;
  // payload: the chunk of a single-chunk delta, remembered in the memo with its result.
  void complete(std::uint32_t tick, Pending& p, std::span<const std::uint8_t> payload);
  bool accept_remembered(const ChunkView& c);
  void complete_shared(std::uint32_t tick, const DecodeMemo::Result& r);
  void show(std::uint32_t tick);
  void evict();
  void drop_pending(std::map<std::uint32_t, Pending>::iterator it);

  StreamConfig config_;
  DecoderOptions options_;
  ModalModel model_;
  std::map<std::uint32_t, DecodeMemo::State> states_;  // complete frames (interned when memo is set)
  std::map<std::uint32_t, Pending> pending_;
  std::optional<std::uint32_t> shown_tick_;     // newest tick with something to show
  SampleFields shown_fields_;                   // its fields once it left pending_
  bool shown_complete_ = false;
  ReconstructedFrame shown_;
  DecodeMemo::Frame shown_shared_;              // set instead of shown_ when the memo holds the frame
  bool shown_dirty_ = true;
  // A frame completed while a newer one was on show (just_completed()).
  std::optional<std::uint32_t> completed_tick_;
  SampleFields late_fields_;
  DecodeMemo::Frame late_shared_;
  ReconstructedFrame late_;
  bool late_converted_ = false;
};

}  // namespace ocean::codec
