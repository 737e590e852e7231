// Decoder: the client side of a stream. Accepts chunks in any order, refuses malformed ones with
// a reason (leaving its state untouched), shows the newest frame (rows of missing chunks keep the
// prediction) and keeps the states of complete frames as baselines for later deltas.
#pragma once

#include "chunk_body.hpp"
#include "decode_memo.hpp"
#include "chunk_format.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "parallel_for.hpp"
#include "ack_window.hpp"
#include "scene_timeline.hpp"
#include "stream_config.hpp"
#include "tick.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace ocean::codec {

struct DecoderOptions {
  std::size_t max_payload = kDefaultMaxPayload;  // larger payloads are refused as oversized
  std::uint32_t history_ticks = 32;  // complete states older than newest complete - this are dropped
  // Largest tick - baseline accepted: the advance costs one step of the recurrence per tick, and a
  // key that took seconds to arrive on a thin link is still a baseline (30 s at 30 Hz).
  std::uint32_t max_lag = 1024;
  std::size_t max_pending = 8;       // incomplete frames kept; the oldest is dropped beyond this
  DecodeMemo* memo = nullptr;        // shared with other decoders of the same stream (same thread)
  // Threads lent by the client for grids of 128 and more: the recurrence, the transforms and the
  // output conversion of a frame run in parts side by side; the bits are the same.
  ParallelFor parallel;
};

class Decoder {
 public:
  // Throws invalid_argument on bad options or a memo of another stream configuration.
  explicit Decoder(const StreamConfig& config, DecoderOptions options = {});

  const StreamConfig& config() const { return config_; }

  // The scene in force from tick `from` on (the Welcome's and every SceneUpdate's, with the
  // update's serial mod 256 as tag). Chunks of ticks with no known scene, or naming another tag,
  // are refused as unknown_scene. Throws std::invalid_argument when the scene does not fit.
  void add_scene(Tick from, std::uint8_t tag, const model::SceneParams& scene) { scenes_.add(from, tag, scene); }
  const SceneTimeline& scenes() const { return scenes_; }
  // The vessels forcing the stream's wake lattice (Welcome.vessels; CODEC.md 7.9).
  void set_vessels(std::vector<model::VesselTrack> vessels) { scenes_.set_vessels(std::move(vessels)); }
  // A new fleet from tick `from` on (a vessel command; SceneTimeline::set_vessels).
  void set_vessels(std::vector<model::VesselTrack> vessels, Tick from) { scenes_.set_vessels(std::move(vessels), from); }

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

  bool is_complete(Tick tick) const { return states_.count(tick) != 0; }
  std::optional<Tick> newest_complete() const;
  std::vector<Tick> complete_ticks() const;  // ascending; what the client may ack
  // The complete ticks an Ack names, kept as frames complete and age out (a load test's
  // thousands of clients ack ten times a second; walking the states each time was 14 % of it).
  const std::optional<protocol::AckWindow>& ack_window() const { return window_; }
  const ModalState* state(Tick tick) const;

 private:
  // A frame as shown: its synthesis before rounding and its corrections so far (to_float).
  struct FrameFields {
    UnroundedFields synthesis;
    Corrections corrections;
  };
  struct Pending;
  static Tick baseline_of(Tick tick, const Pending& p);
  struct Pending {
    Tick baseline = 0;
    bool key = false;
    bool modeled = false;
    std::uint16_t count = 0;
    std::vector<bool> got;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    std::uint16_t received = 0;
    ModalState predicted;                  // delta: advanced baseline state; modeled key: the model's
    FrameFields fields;  // synthesis: of the prediction (delta, modeled key), else at completion
    std::vector<KeyCoefficient> key_coefficients;  // key: filled as chunks arrive
    std::uint8_t pos_shift = 0, vel_shift = 0;
    DecodeMemo::Payloads key_payloads;  // with a memo: the key's chunks by index, to look it up whole
  };

  ChunkError check(const ChunkView& c, const ChunkHeader& h, const BodyLayout& layout) const;
  // payload: the chunk of a single-chunk delta, remembered in the memo with its result.
  void complete(Tick tick, Pending& p, std::span<const std::uint8_t> payload);
  bool accept_remembered(const ChunkView& c);
  void start_pending(Pending& p, const ChunkView& c, const ChunkHeader& h, std::uint32_t spectral_items);
  void complete_shared(Tick tick, const DecodeMemo::Result& r);
  void show(Tick tick);
  void hold(Tick tick, DecodeMemo::State state);
  void evict();
  void drop_pending(std::map<Tick, Pending>::iterator it);
  void recycle(DecodeMemo::State&& state);
  void recycle(FrameFields&& fields) {
    if (fields.synthesis.channels[0].capacity() <= spare_fields_.synthesis.channels[0].capacity()) return;
    spare_fields_ = std::move(fields);
    for (int ch = 0; ch < kCorrectionChannels; ++ch) spare_fields_.corrections[ch].clear();
  }

  StreamConfig config_;
  DecoderOptions options_;
  ParallelFor parallel_;  // options_.parallel where the grid is worth it
  ModalModel model_;
  SceneTimeline scenes_;
  std::map<Tick, DecodeMemo::State> states_;  // complete frames (interned when memo is set)
  std::optional<protocol::AckWindow> window_;  // of states_' ticks
  std::map<Tick, Pending> pending_;
  std::optional<Tick> shown_tick_;              // newest tick with something to show
  FrameFields shown_fields_;                    // its fields once it left pending_
  bool shown_complete_ = false;
  Tick shown_baseline_ = 0;                     // of shown_fields_
  ReconstructedFrame shown_;
  DecodeMemo::Frame shown_shared_;              // set instead of shown_ when the memo holds the frame
  bool shown_dirty_ = true;
  // A frame completed while a newer one was on show (just_completed()).
  std::optional<Tick> completed_tick_;
  FrameFields late_fields_;
  Tick late_baseline_ = 0;
  DecodeMemo::Frame late_shared_;
  ReconstructedFrame late_;
  bool late_converted_ = false;
  // The buffers of a frame no longer needed, taken by the next one: a 256 choppy frame is 4 MB,
  // which allocated afresh would be faulted in page by page every frame.
  FrameFields spare_fields_;
  ModalState spare_state_;  // likewise the buffers of an evicted state (1 MB at 256)
};

}  // namespace ocean::codec
