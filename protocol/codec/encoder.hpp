// Encoder: the server side of a stream. Holds recent truth frames, the scenes announced to its
// clients and the decoder states it has produced (keyed by StateId), and encodes a tick as a key
// (the scene model's state plus corrections, or explicit coefficients when the model is far from
// the truth) or as a delta from any held state, predicting from exactly the state the decoder will
// hold (closed loop). Results are cached per (tick, baseline) so one encoding serves every client
// sharing that baseline.
#pragma once

#include "chunk_body.hpp"
#include "chunk_format.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "advanced_state.hpp"
#include "scene_timeline.hpp"
#include "state_hash.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace ocean::codec {

struct EncoderOptions {
  std::size_t max_payload = kDefaultMaxPayload;  // payload bytes per chunk, 64..65000
  std::uint32_t history_ticks = 32;  // truth and states older than newest truth - this are dropped
  // ... except the states of keys, kept this long: a key that reaches a client late on a thin link
  // is still its baseline (0 = as history_ticks).
  std::uint32_t key_history_ticks = 0;
  // Encoded frames (keys and deltas, with their reconstructions) are cached to hand the same frame
  // out again; this many newest ticks of them (0 = as history_ticks). The states stay for their
  // history either way. A server that only encodes its newest tick sets 1: desktop frames hold
  // 0.8 MB of reconstruction each, and a few hundred of them were most of its memory.
  std::uint32_t frame_cache_ticks = 0;
  int key_precision_bits = 6;        // key position error about step * 2^-bits rms (0..16)
  int key_velocity_extra_bits = 3;   // key velocity this many bits finer than position (0..16)
  // A modeled key with more corrections than this share of its samples falls back to explicit
  // coefficients (the sim then differs from the scene model the decoder runs).
  double modeled_key_max_correction_share = 0.02;
};

// A view of one sim frame (row-major z * n + x), per channel (common/channels.hpp): each channel
// the stream carries is required - the slopes with normals, the displacement and its derivatives
// (choppiness applied) when it is choppy.
using TruthView = PerChannel<std::span<const float>>;

struct FrameStats {
  std::size_t payload_bytes = 0;
  std::size_t corrections_height = 0, corrections_slope = 0, corrections_choppy = 0;
  BodyCost cost;  // ideal bits per section (statistics)
};

struct EncodedFrame {
  StateId id;    // the decoder state this frame leaves behind once complete
  StateId base;  // the state it was predicted from (== id for keys)
  bool key = false;
  std::vector<Chunk> chunks;
  ReconstructedFrame reconstruction;  // exactly what the decoder shows once all chunks arrive
  FrameStats stats;
};

class Encoder {
 public:
  explicit Encoder(const StreamConfig& config, EncoderOptions options = {});  // throws invalid_argument

  const StreamConfig& config() const { return config_; }
  const EncoderOptions& options() const { return options_; }

  // The scene in force from tick `from` on, as the clients learn it (SceneUpdate): needed before the
  // first encode, and announced to the decoders before any frame of its ticks reaches them.
  void set_scene(Tick from, std::uint8_t tag, const model::SceneParams& scene);
  const SceneTimeline& scenes() const { return scenes_; }
  // The vessels forcing the stream's wake lattice, as its decoders are told (CODEC.md 7.9).
  void set_vessels(std::vector<model::VesselTrack> vessels) { scenes_.set_vessels(std::move(vessels)); }
  // A new fleet from tick `from` on (a vessel command; SceneTimeline::set_vessels).
  void set_vessels(std::vector<model::VesselTrack> vessels, Tick from) { scenes_.set_vessels(std::move(vessels), from); }
  // That scene's model, built ahead elsewhere (SceneTimeline::provide_model): the first frame of
  // a new scene then costs no model build (a desktop stream's took 50-100 ms).
  void provide_scene_model(Tick from, const model::SceneParams& scene, std::shared_ptr<const SceneModel> model) {
    scenes_.provide_model(from, scene, std::move(model));
  }

  // Stores the truth for a tick (copied). Ticks older than newest - history_ticks are evicted
  // together with their states. A value beyond the stream's 2^20 steps (or not finite) is clamped
  // to the last step (0) and counted in saturated_samples(); wrong sizes throw invalid_argument.
  void add_truth(Tick tick, const TruthView& truth);
  std::uint64_t saturated_samples() const { return saturated_; }

  // A key needs the truth of its tick (and of tick - 1 when the scene model misses the truth and
  // explicit coefficients are sent). Throws std::invalid_argument when the truth is missing.
  std::shared_ptr<const EncodedFrame> encode_key(Tick tick);

  // A delta for `tick` predicted from `baseline` (a state this encoder produced, baseline.tick <
  // tick). Its id is that of an earlier delta of `tick` when both leave the very same state.
  // Throws std::invalid_argument when the truth or the baseline state is gone.
  std::shared_ptr<const EncodedFrame> encode_delta(Tick tick, StateId baseline);

  bool has_state(StateId id) const { return states_.count(id) != 0; }
  const ModalState* state(StateId id) const;
  // Drops every state and cached frame (truth and scenes stay): for a stream nobody receives, whose
  // key states would otherwise stay key_history_ticks. Later deltas need a new key first.
  // Returns false when there was nothing to drop.
  bool forget_states();

 private:
  using TruthFrame = PerChannel<std::vector<float>>;
  struct KeyCoding {
    bool modeled = true;
    std::vector<KeyCoefficient> coefficients;  // explicit keys only
    int pos_shift = 0, vel_shift = 0;
  };
  Corrections correct(Tick tick, const ModalState& predicted);
  // correct(), run once per distinct prediction of a tick: deltas from different baselines (and
  // a modeled key) mostly predict the very same state, and its corrections and fields follow
  // from that state and the tick's truth alone.
  Corrections correct_once(Tick tick, const ModalState& predicted);
  std::shared_ptr<const EncodedFrame> explicit_key(Tick tick);
  std::shared_ptr<EncodedFrame> finish_frame(Tick tick, ModalState predicted, const Corrections& corrections,
                                             const KeyCoding* key, StateId base);
  void chunk_frame(EncodedFrame& frame, const BodyLayout& layout, const ChunkHeader& proto,
                   const std::vector<KeyCoefficient>& key_coefficients, const Corrections& corrections);
  void evict();

  StreamConfig config_;
  EncoderOptions options_;
  ModalModel model_;
  SceneTimeline scenes_;
  std::map<Tick, TruthFrame> truth_;
  std::map<StateId, ModalState> states_;
  std::map<Tick, std::shared_ptr<const EncodedFrame>> keys_;  // cached frames (frame_cache_ticks)
  std::map<Tick, StateId> key_ids_;                             // every key's state, for key_history_ticks
  std::map<std::pair<Tick, StateId>, std::shared_ptr<const EncodedFrame>> deltas_;
  std::map<StateId, AdvancedState> advanced_;  // where each baseline's deltas start
  // This tick's distinct predictions with what correct() made of them.
  struct Prediction {
    ModalState state;
    Corrections corrections;
    SampleFields fields;
  };
  static constexpr std::size_t kMaxPredictionsPerTick = 8;
  Tick predictions_tick_ = 0;
  std::vector<Prediction> predictions_;
  std::uint32_t next_serial_ = 1;
  Tick newest_ = 0;
  bool have_truth_ = false;
  SampleFields fields_;  // scratch
  std::uint64_t saturated_ = 0;
};

}  // namespace ocean::codec
