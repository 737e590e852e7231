// EpochWake: the wake at any tick as a function of the vessels' tracks alone, with a bounded
// history, so that a server started late, a replica and a load test's ground truth all compute the
// same bits. Time is cut into epochs of `epoch_ticks`; the wake at tick t is the response to the
// hulls' forcing during the epoch before t's and during t's own, each started at rest at its epoch's
// first tick. Forcing older than that is dropped: with the default damping its waves have decayed
// to e^{-decay x epoch} of their size when they go. The codec's decoders drop them at the same
// ticks (CODEC.md 7.9). Two fields are
// stepped, so a wake costs twice one field; catching up from nothing costs at most two epochs.
#pragma once

#include "vessel_track.hpp"
#include "wake_field.hpp"

#include <cstdint>
#include <map>
#include <vector>

namespace ocean::sim {

// The epoch ocean-server uses (StreamParams.wake.epoch_ticks): a minute. With the default decay
// (0.05/s) the waves it drops have faded to e^{-3} of their size; a decoder that joins computes
// the wake of two epochs at most from the tracks (CODEC.md 7.9).
inline std::int64_t wake_epoch_ticks(int rate_hz) { return 60 * static_cast<std::int64_t>(rate_hz); }

class EpochWake {
 public:
  // Tracks in world metres; the region's corner is at (origin_x_m, origin_z_m); tick t is at
  // t / rate_hz seconds, and the step from t holds each hull at its pose at (t + 0.5) / rate_hz.
  EpochWake(const WakeRegion& region, double origin_x_m, double origin_z_m, std::vector<model::VesselTrack> tracks,
            int rate_hz, std::int64_t epoch_ticks);

  // The wake at `tick` (any tick >= 0; stepping forward is cheap, going back recomputes).
  void advance_to(std::int64_t tick);
  // The tracks from tick `from` on (a vessel command): they must press as the current ones do
  // before `from` (a command ends and starts presences there), so the parts stepped up to `from`
  // stay; one stepped past it starts again.
  void set_tracks(std::vector<model::VesselTrack> tracks, std::int64_t from);
  const std::vector<model::VesselTrack>& tracks() const { return tracks_; }
  // The water's depth from tick `from` on (a change of scene), as the codec's recurrence follows
  // the scene in force at each tick (CODEC.md 7.9): a step from tick t uses the depth in force at
  // t. Parts stepped past `from` start again.
  void set_depth(double depth_m, std::int64_t from);
  // The fields whose sum is the wake at the tick last advanced to (one or two).
  std::vector<const WakeField*> fields() const;

  const WakeRegion& region() const { return region_; }
  std::int64_t tick() const { return tick_; }

 private:
  struct Part {
    std::int64_t start = 0;  // its epoch's first tick: at rest there, forced until the next epoch
    std::int64_t reached = 0;
    WakeField field;
  };
  void step(Part& part);
  Part fresh(std::int64_t start) const;
  void restart_after(std::int64_t from);  // parts stepped past `from` start again

  WakeRegion region_;
  double origin_x_m_, origin_z_m_;
  std::vector<model::VesselTrack> tracks_;
  int rate_hz_;
  std::int64_t epoch_ticks_;
  std::int64_t tick_ = -1;
  std::vector<Part> parts_;  // the previous epoch's (if any), then the current one's
  std::map<std::int64_t, double> depths_;  // from tick (the region's own depth before the first)
  std::vector<HullPose> poses_;
};

}  // namespace ocean::sim
