// SceneTimeline: the scenes a stream's encoder or decoder knows, each in force from its effective
// tick on (CODEC.md 7.5). Advancing a state across an effective tick replaces it by the new
// scene's model state there, so a weather change costs no bytes and no keyframe; between changes
// a state advances by the recurrence of the scene in force (its depth sets w).
#pragma once

#include "modal_model.hpp"
#include "model_cache.hpp"
#include "scene_model.hpp"
#include "stream_config.hpp"
#include "tick.hpp"
#include "wake_forcing.hpp"

#include <cstdint>
#include <map>
#include <memory>

namespace ocean::codec {

class SceneTimeline {
 public:
  struct Entry {
    std::uint8_t tag = 0;     // SceneUpdate.serial mod 256; every chunk names the tag of its tick
    model::SceneParams scene;
  };

  explicit SceneTimeline(const StreamConfig& config);
  SceneTimeline(SceneTimeline&&) noexcept;
  SceneTimeline& operator=(SceneTimeline&&) noexcept;
  ~SceneTimeline();

  // The scene in force from `from` on (replacing an entry of the same tick). Throws
  // std::invalid_argument when the scene does not fit the stream (grid larger than its size).
  void add(Tick from, std::uint8_t tag, const model::SceneParams& scene);
  // The entry in force at `tick`, or nullptr before the first one.
  const Entry* at(Tick tick) const;
  // The first tick of the entry in force at `tick` (at(tick) must not be null).
  Tick start_of(Tick tick) const;

  // The scene model's state of `tick` (a modeled key). at(tick) must not be null.
  void model_state(Tick tick, ModalState& out) const;
  // `state` of tick `from` becomes the state of tick `to` (>= from): replaced by the model state
  // at the last effective tick in (from, to], then advanced by the recurrence of that scene.
  void advance(ModalState& state, Tick from, Tick to) const;
  // The same, from `state` into `out` (another state), which need not be a copy of it first; the
  // recurrence's modes side by side with `parallel`.
  void advance(const ModalState& state, Tick from, Tick to, ModalState& out, const ParallelFor& parallel = {}) const;
  // Builds what model_state(to) (key) or advance(from, to) (delta) will need; false when the scene
  // model cannot be built (a scene that does not describe this stream). Afterwards those calls
  // cannot throw, so a decoder checks this before it changes anything.
  bool prepare(Tick from, Tick to, bool key) const;

  // Models come from `cache` (not owned; it must outlive this timeline) instead of being built
  // here: for decoders sharing a DecodeMemo.
  void share_models(ModelCache* cache) { cache_ = cache; }
  // The config a scene's model is built with (this stream's, with the scene's depth), and a model
  // built elsewhere (another thread, ahead of its tick) for the entry from `from`: ignored unless
  // that entry still holds `scene`. Without it the model is built here on first use.
  StreamConfig model_config(const model::SceneParams& scene) const;
  void provide_model(Tick from, const model::SceneParams& scene, std::shared_ptr<const SceneModel> model);

  // The vessels whose hulls force the wake lattice (CODEC.md 7.9), from now on in every advance;
  // none: the wake rings down freely. Throws std::invalid_argument for a stream without a wake.
  void set_vessels(std::vector<model::VesselTrack> vessels);
  // The fleet from tick `from` on (a SceneUpdate's vessels): its presences agree with the current
  // fleet's before `from`, so the wake history computed up to `from` is kept.
  void set_vessels(std::vector<model::VesselTrack> vessels, Tick from);

  // Forgets entries no longer in force at `tick` or later.
  void forget_before(Tick tick);
  std::size_t size() const { return entries_.size(); }

 private:
  struct Held;
  const Held& held_at(Tick tick) const;
  const SceneModel& model_of(const Held& held) const;
  const ModalModel& recurrence_of(const Held& held) const;
  StreamConfig with_depth(const Held& held) const;
  // The wake lattice's timeline (scene_timeline_wake.cpp, CODEC.md 7.9).
  void advance_with_wake(ModalState& state, Tick from, Tick to) const;
  void walk_wake(ModalState& state, Tick from, Tick to) const;
  bool crosses_epoch(Tick from, Tick to) const;
  const ModalModel& recurrence_near(Tick tick) const;
  void add_wake_history(Tick tick, ModalState& state) const;
  const WakeForcing::Part& wake_part(std::int64_t epoch, Tick tick) const;

  StreamConfig config_;
  std::map<Tick, std::unique_ptr<Held>> entries_;
  ModelCache* cache_ = nullptr;
  // Mutable: it keeps each tick's pressure for the next advance across it.
  std::shared_ptr<WakeForcing> forcing_;  // the ModelCache's when shared
};

}  // namespace ocean::codec
