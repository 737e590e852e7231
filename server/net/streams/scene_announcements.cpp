#include "scene_announcements.hpp"

#include <iterator>
#include <stdexcept>

namespace ocean::server {

SceneAnnouncements::SceneAnnouncements(SceneSchedule schedule, Tick lead_ticks)
    : schedule_(std::move(schedule)), lead_(lead_ticks) {}

std::vector<AnnouncedScene> SceneAnnouncements::start(Tick now) {
  announced_.clear();
  const auto& changes = schedule_.changes();
  AnnouncedScene current{0, 0, schedule_.base()};
  next_entry_ = 0;
  while (next_entry_ < changes.size() && static_cast<Tick>(changes[next_entry_].tick) <= now) {
    current = AnnouncedScene{static_cast<Tick>(changes[next_entry_].tick), static_cast<std::uint32_t>(next_entry_ + 1),
                             changes[next_entry_].scene};
    ++next_entry_;
  }
  announced_[current.from] = current;
  std::vector<AnnouncedScene> out{current};
  for (const AnnouncedScene& a : announce(now)) out.push_back(a);
  return out;
}

std::vector<AnnouncedScene> SceneAnnouncements::announce(Tick now) {
  std::vector<AnnouncedScene> out;
  const auto& changes = schedule_.changes();
  while (next_entry_ < changes.size() && static_cast<Tick>(changes[next_entry_].tick) <= now + lead_) {
    const ScheduledScene& entry = changes[next_entry_];
    const auto from = static_cast<Tick>(entry.tick);
    const AnnouncedScene scene{from, static_cast<std::uint32_t>(next_entry_ + 1), entry.scene};
    ++next_entry_;
    // An admin scene of the same tick wins (the producer applies the schedule, then the admin's).
    if (announced_.count(from)) continue;
    announced_[from] = scene;
    out.push_back(scene);
  }
  return out;
}

const AnnouncedScene& SceneAnnouncements::add_at(Tick from, const model::SceneParams& scene,
                                                 std::optional<std::vector<model::VesselTrack>> vessels) {
  const std::uint32_t serial = in_force(from).serial + 128;
  return announced_[from] = AnnouncedScene{from, serial, scene, std::move(vessels)};
}

const AnnouncedScene& SceneAnnouncements::add_logged(Tick from, const model::SceneParams& scene,
                                                     std::optional<std::vector<model::VesselTrack>> vessels) {
  std::uint32_t predecessor = 0;  // the base scene's
  Tick predecessor_from = 0;
  const auto& changes = schedule_.changes();
  for (std::size_t i = 0; i < changes.size() && static_cast<Tick>(changes[i].tick) <= from; ++i) {
    predecessor = static_cast<std::uint32_t>(i + 1);
    predecessor_from = static_cast<Tick>(changes[i].tick);
  }
  if (auto logged = logged_.upper_bound(from); logged != logged_.begin() && std::prev(logged)->first >= predecessor_from)
    predecessor = std::prev(logged)->second;
  const std::uint32_t serial = predecessor + 128;
  logged_[from] = serial;
  return announced_[from] = AnnouncedScene{from, serial, scene, std::move(vessels)};
}

const AnnouncedScene& SceneAnnouncements::in_force(Tick tick) const {
  auto it = announced_.upper_bound(tick);
  if (it == announced_.begin()) throw std::logic_error("SceneAnnouncements: nothing announced for this tick");
  return std::prev(it)->second;
}

std::vector<AnnouncedScene> SceneAnnouncements::after(Tick tick) const {
  std::vector<AnnouncedScene> out;
  for (auto it = announced_.upper_bound(tick); it != announced_.end(); ++it) out.push_back(it->second);
  return out;
}

void SceneAnnouncements::forget_before(Tick tick) {
  auto keep = announced_.upper_bound(tick);
  if (keep == announced_.begin()) return;
  announced_.erase(announced_.begin(), std::prev(keep));
}

}  // namespace ocean::server
