#include "scene_schedule.hpp"

#include <algorithm>

namespace ocean::server {

SceneSchedule::SceneSchedule(model::SceneParams base, std::vector<ScheduledScene> changes)
    : base_(base), changes_(std::move(changes)) {}

const model::SceneParams& SceneSchedule::scene_at(std::int64_t tick) const {
  // changes_ is sorted by tick (validate() insists); find the last one not after `tick`.
  const auto after = std::upper_bound(changes_.begin(), changes_.end(), tick,
                                      [](std::int64_t t, const ScheduledScene& c) { return t < c.tick; });
  return after == changes_.begin() ? base_ : std::prev(after)->scene;
}

std::string SceneSchedule::validate() const {
  for (std::size_t i = 0; i < changes_.size(); ++i) {
    const ScheduledScene& change = changes_[i];
    const std::string where = "schedule entry " + std::to_string(i + 1) + " (tick " + std::to_string(change.tick) + ")";
    if (i > 0 && change.tick <= changes_[i - 1].tick)
      return where + ": ticks must increase strictly; the previous entry is at tick " +
             std::to_string(changes_[i - 1].tick);
    const model::SceneParams& s = change.scene;
    if (s.size_x != base_.size_x || s.size_z != base_.size_z || s.patch_x_m != base_.patch_x_m ||
        s.patch_z_m != base_.patch_z_m || s.seed != base_.seed || s.gravity_mps2 != base_.gravity_mps2)
      return where + ": size, patch and seed cannot be scheduled (they define the grid every stream samples)";
    if (const std::string error = model::validate(s); !error.empty()) return where + ": " + error;
  }
  return {};
}

}  // namespace ocean::server
