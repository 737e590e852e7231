// DecodeMemo: lets many decoders of one stream share their work, exactly. Complete states are
// interned by content, so equal states are one object; a single-chunk delta decoded from an
// interned state is remembered by (that object, tick, payload bytes), and a decoder that gets the
// same bytes on the same baseline object takes the remembered state and frame instead of
// decoding again; keys are remembered by the bytes of all their chunks. A hit needs identical inputs, so it changes no result: a load test's hundreds
// of clients of one stream decode each distinct frame once. One memo per thread (not locked).
#pragma once

#include "advanced_state.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "model_cache.hpp"
#include "scene_timeline.hpp"
#include "stream_config.hpp"
#include "tick.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

namespace ocean::codec {

class DecodeMemo {
 public:
  using State = std::shared_ptr<const ModalState>;
  using Frame = std::shared_ptr<const ReconstructedFrame>;
  struct Result {
    State state;  // the frame's complete state (interned)
    Frame frame;  // what the decoder shows for it; frame->shared_id != 0
  };
  struct Counts {
    std::uint64_t hits = 0, misses = 0, interned = 0, intern_hits = 0;
  };

  // window_ticks: entries older than the newest tick seen minus this are forgotten.
  explicit DecodeMemo(const StreamConfig& config, std::uint32_t window_ticks = 64);

  const StreamConfig& config() const { return config_; }
  // The scene models and recurrences every decoder of this memo shares.
  ModelCache& models() { return models_; }
  const Counts& counts() const { return counts_; }

  // The one object holding a state equal to `state` at `tick`.
  State intern(Tick tick, ModalState&& state);

  const Result* find(const State& baseline, Tick tick, std::span<const std::uint8_t> payload);
  // `frame` gets a fresh shared_id; returns the stored result.
  const Result& remember(const State& baseline, Tick tick, std::span<const std::uint8_t> payload,
                         State state, ReconstructedFrame&& frame);

  // `out` = `baseline` (the interned state of tick `from`) advanced to `to` through `scenes`,
  // from where the memo's decoders last advanced the same baseline object.
  void advance(const State& baseline, Tick from, Tick to, const SceneTimeline& scenes, ModalState& out);

  // Keys, by the payloads of all their chunks in index order.
  using Payloads = std::vector<std::vector<std::uint8_t>>;
  const Result* find_key(Tick tick, const Payloads& chunks);
  // A key of one chunk, before its decoder does any work (a miss is counted when it completes).
  const Result* find_key(Tick tick, std::span<const std::uint8_t> payload);
  const Result& remember_key(Tick tick, const Payloads& chunks, State state, ReconstructedFrame&& frame);

 private:
  struct Key {
    const ModalState* baseline;
    Tick tick;
    std::uint64_t payload_hash;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  struct Entry {
    State baseline;  // held so its address cannot be reused while the key names it
    std::vector<std::uint8_t> payload;
    Result result;
  };

  struct Advanced {
    State baseline;  // held, as in Entry
    Tick from;
    AdvancedState state;
  };

  struct KeyEntry {
    Tick tick;
    Payloads chunks;
    Result result;
  };

  void saw_tick(Tick tick);
  Result shared_result(State state, ReconstructedFrame&& frame);  // frame gets a fresh shared_id

  StreamConfig config_;
  ModelCache models_;
  std::uint32_t window_;
  Tick newest_ = 0;
  std::uint64_t frame_ids_ = 0;
  std::unordered_map<Key, std::vector<Entry>, KeyHash> deltas_;
  std::multimap<std::uint64_t, KeyEntry> keys_;  // by content hash
  std::unordered_map<const ModalState*, Advanced> advanced_;  // by baseline object
  std::map<Tick, std::unordered_multimap<std::uint64_t, State>> states_;  // tick -> content hash -> state
  Counts counts_;
};

}  // namespace ocean::codec
