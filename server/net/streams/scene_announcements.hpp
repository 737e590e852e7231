// SceneAnnouncements: which scenes the clients are told of, and when. A weather change reaches
// every client as a SceneUpdate `lead` ticks before it takes effect, so both sides of every codec
// stream switch scene at the same tick with no keyframe (CODEC.md 7.5). Schedule entries from the
// config are announced `lead` ticks ahead; an admin change takes effect `lead` ticks after it is
// accepted. Every scene has a serial that replicas agree on: the base scene is 0, schedule entry
// i is i + 1, an admin scene is its predecessor's + 128 (so neighbours never share a tag mod 256).
#pragma once

#include "scene_schedule.hpp"
#include "tick.hpp"
#include "vessel_track.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace ocean::server {

struct AnnouncedScene {
  Tick from = 0;
  std::uint32_t serial = 0;
  model::SceneParams scene;
  // A vessel command's: the whole fleet from `from` on (the scene itself unchanged).
  std::optional<std::vector<model::VesselTrack>> vessels = std::nullopt;
};

class SceneAnnouncements {
 public:
  SceneAnnouncements(SceneSchedule schedule, Tick lead_ticks);

  Tick lead_ticks() const { return lead_; }
  // The first tick the server runs: the scene then in force and every schedule entry due within
  // the lead are announced (returned, oldest first). Later ticks: announce(now) returns the
  // entries that came within the lead since the last call.
  std::vector<AnnouncedScene> start(Tick now);
  std::vector<AnnouncedScene> announce(Tick now);
  // An admin's scene from now + lead on (until the next schedule entry), already announced.
  const AnnouncedScene& add_admin(Tick now, const model::SceneParams& scene,
                                  std::optional<std::vector<model::VesselTrack>> vessels = std::nullopt) {
    return add_at(now + lead_, scene, std::move(vessels));
  }
  const AnnouncedScene& add_at(Tick from, const model::SceneParams& scene,
                               std::optional<std::vector<model::VesselTrack>> vessels = std::nullopt);
  // A fleet timeline's entry from tick `from`, past or future. Its serial is its predecessor's +
  // 128, the predecessor found from the schedule and the entries logged before it alone (an entry
  // wins over a schedule entry of its tick): a replica started after the entry numbers it as the
  // replicas that announced it did.
  const AnnouncedScene& add_logged(Tick from, const model::SceneParams& scene,
                                   std::optional<std::vector<model::VesselTrack>> vessels = std::nullopt);

  // The announced scene in force at `tick` (start() must have run).
  const AnnouncedScene& in_force(Tick tick) const;
  // Announced scenes that take effect after `tick`, oldest first (a joining client needs them).
  std::vector<AnnouncedScene> after(Tick tick) const;
  // Forgets scenes no longer in force at `tick` or later.
  void forget_before(Tick tick);

 private:
  SceneSchedule schedule_;
  Tick lead_;
  std::size_t next_entry_ = 0;           // the first schedule entry not announced yet
  std::map<Tick, AnnouncedScene> announced_;
  std::map<Tick, std::uint32_t> logged_;  // every timeline entry's serial, by its first tick
};

}  // namespace ocean::server
