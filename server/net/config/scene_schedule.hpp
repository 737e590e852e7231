// SceneSchedule: scene changes planned in the config ("from tick T, wind = ..."). Each entry holds
// the whole scene in force from its tick on, so the scene for any tick is a lookup, not a replay.
#pragma once

#include "scene_params.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ocean::server {

struct ScheduledScene {
  std::int64_t tick = 0;   // absolute tick index (counted from the epoch)
  model::SceneParams scene;  // the complete scene from this tick on
};

class SceneSchedule {
 public:
  SceneSchedule() = default;
  SceneSchedule(model::SceneParams base, std::vector<ScheduledScene> changes);

  const model::SceneParams& base() const { return base_; }
  const std::vector<ScheduledScene>& changes() const { return changes_; }

  // The scene in force at `tick`: the last change with change.tick <= tick, else the base.
  const model::SceneParams& scene_at(std::int64_t tick) const;

  // Empty when usable; otherwise names the entry (by its tick) and what is wrong: ticks must rise
  // strictly, every scene must pass model::validate, and only weather may change (not the grid or seed,
  // which would change what every stream's samples mean).
  std::string validate() const;

 private:
  model::SceneParams base_;
  std::vector<ScheduledScene> changes_;
};

}  // namespace ocean::server
