// SceneTimeline: lazily built models per scene; recurrences shared by scenes of one depth.
#include "scene_timeline.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ocean::codec {

// Both are built on first use: the scene model (h0 tables) only for keys and changes of scene,
// the recurrence (whose a(k) depends on the scene's depth) only once a state advances in it.
struct SceneTimeline::Held {
  Entry entry;
  mutable std::shared_ptr<const ModalModel> recurrence;
  mutable std::shared_ptr<const SceneModel> model;
};

SceneTimeline::SceneTimeline(const StreamConfig& config) : config_(config) {}
SceneTimeline::SceneTimeline(SceneTimeline&&) noexcept = default;
SceneTimeline& SceneTimeline::operator=(SceneTimeline&&) noexcept = default;
SceneTimeline::~SceneTimeline() = default;

void SceneTimeline::add(Tick from, std::uint8_t tag, const model::SceneParams& scene) {
  if (config_.cascades.empty() && (scene.size_x < config_.grid || scene.size_z < config_.grid))
    throw std::invalid_argument("SceneTimeline::add: the scene's grid " + std::to_string(scene.size_x) + "x" +
                                std::to_string(scene.size_z) + " is smaller than the stream's " +
                                std::to_string(config_.grid));
  auto held = std::make_unique<Held>();
  held->entry = Entry{tag, scene};
  entries_[from] = std::move(held);
}

const SceneTimeline::Held& SceneTimeline::held_at(Tick tick) const {
  auto it = entries_.upper_bound(tick);
  if (it == entries_.begin()) throw std::logic_error("SceneTimeline: no scene for tick " + std::to_string(tick));
  return *std::prev(it)->second;
}

const SceneTimeline::Entry* SceneTimeline::at(Tick tick) const {
  auto it = entries_.upper_bound(tick);
  return it == entries_.begin() ? nullptr : &std::prev(it)->second->entry;
}

Tick SceneTimeline::start_of(Tick tick) const {
  auto it = entries_.upper_bound(tick);
  if (it == entries_.begin()) throw std::logic_error("SceneTimeline: no scene for tick " + std::to_string(tick));
  return std::prev(it)->first;
}

StreamConfig SceneTimeline::with_depth(const Held& held) const { return model_config(held.entry.scene); }

StreamConfig SceneTimeline::model_config(const model::SceneParams& scene) const {
  StreamConfig c = config_;
  c.depth_m = model::wire_depth(scene.depth_m);
  return c;
}

void SceneTimeline::provide_model(Tick from, const model::SceneParams& scene, std::shared_ptr<const SceneModel> model) {
  const auto it = entries_.find(from);
  if (it != entries_.end() && it->second->entry.scene == scene && !it->second->model) it->second->model = std::move(model);
}

const SceneModel& SceneTimeline::model_of(const Held& held) const {
  if (!held.model)
    held.model = cache_ ? cache_->scene_model(with_depth(held), held.entry.scene)
                        : std::make_shared<const SceneModel>(with_depth(held), held.entry.scene);
  return *held.model;
}

void SceneTimeline::model_state(Tick tick, ModalState& out) const {
  model_of(held_at(tick)).state_at(tick, out);
  add_wake_history(tick, out);
}

bool SceneTimeline::prepare(Tick from, Tick to, bool key) const {
  if (!at(to) || (!key && !at(from))) return false;
  const Tick start = start_of(to);
  if (!key && start <= from) return true;  // within one scene: the recurrence alone
  try {
    (void)model_of(held_at(key ? to : start));
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

void SceneTimeline::advance(ModalState& state, Tick from, Tick to) const {
  if (config_.has_wake()) return advance_with_wake(state, from, to);
  Tick now = from;
  const Tick start = start_of(to);
  if (start > from) {
    model_state(start, state);
    now = start;
  }
  recurrence_of(held_at(now)).advance(state, to - now);
}

const ModalModel& SceneTimeline::recurrence_of(const Held& held) const {
  if (!held.recurrence)
    held.recurrence = cache_ ? cache_->recurrence(with_depth(held)) : std::make_shared<const ModalModel>(with_depth(held));
  return *held.recurrence;
}

void SceneTimeline::advance(const ModalState& state, Tick from, Tick to, ModalState& out,
                            const ParallelFor& parallel) const {
  if (start_of(to) > from || crosses_epoch(from, to)) {
    if (config_.has_wake()) out = state;  // the wake rides through the change
    advance(out, from, to);  // else from the scene model's state: `state` plays no part
    return;
  }
  recurrence_of(held_at(from)).advance(state, out, to - from, parallel, forcing_.get(), from);
}

void SceneTimeline::forget_before(Tick tick) {
  auto keep = entries_.upper_bound(tick);
  if (keep == entries_.begin()) return;
  entries_.erase(entries_.begin(), std::prev(keep));
}

}  // namespace ocean::codec
