// GroundTruth: the frame the server should have streamed for a tick, computed once per (tick, grid)
// from the scene in the Welcome (and every SceneUpdate from its effective tick) with the same
// sim the server runs, and shared by every simulated client.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "message_types.hpp"
#include "cascade_set.hpp"
#include "epoch_wake.hpp"
#include "wake_frame.hpp"
#include "ocean.hpp"

namespace ocean::loadtest {

class GroundTruth {
 public:
  // tick_rate_hz: the server's tick rate (1 / Welcome.tick_period_s, rounded). choppy: the stream
  // carries displacement and its derivatives (Welcome.stream.choppy), so the truth evaluates them
  // too; five more transforms a frame, spent only when they are checked.
  // cascades: the stream's (Welcome.stream.cascades), whose frames are their cascades' one after
  // the other; empty for a band of the scene's grid.
  explicit GroundTruth(int tick_rate_hz, bool choppy = false, std::size_t cache_frames = 256,
                       std::vector<Cascade> cascades = {});

  // The stream's wake lattice and the vessels forcing it (Welcome.stream.wake, Welcome.vessels):
  // frames then end with the wake as the server computes it (sim::EpochWake).
  void set_wake(const WakeLattice& lattice, std::vector<model::VesselTrack> vessels, const protocol::SceneParams& scene);

  // A vessel command's fleet from tick `from` on (SceneUpdate.vessels).
  void set_vessels(std::vector<model::VesselTrack> vessels, Tick from);

  // The scene in force from effective_tick on. Re-announcing a known scene changes nothing, so
  // every client may report the Welcome and SceneUpdates it sees.
  void set_scene(Tick effective_tick, const protocol::SceneParams& scene);

  // The grid x grid band (heights, slopes and, when choppy, displacement and its derivatives) at
  // tick, or every cascade's frame one after the other. Shared, so that a caller may compare a frame with it after handing the truth to another
  // thread (load_run.cpp locks around at() only).
  std::shared_ptr<const sim::Frame> at(Tick tick, int grid);

  // Server time of a tick as the server computes it (whole seconds and the fraction apart).
  double time_of(Tick tick) const;
  std::uint64_t evaluations() const { return evaluations_; }
  std::size_t scenes() const { return scenes_.size(); }

 private:
  struct SceneEntry {
    Tick effective_tick;
    protocol::SceneParams wire;
    std::unique_ptr<sim::Ocean> ocean;
    std::unique_ptr<sim::CascadeSet> cascades;  // the stream's, if it has any
  };
  SceneEntry entry(Tick effective_tick, const protocol::SceneParams& scene) const;
  SceneEntry* scene_for(Tick tick);
  void forget_from(Tick tick);  // cached frames of this tick and later

  int rate_hz_;
  bool choppy_;
  std::size_t cache_frames_;
  std::vector<Cascade> cascades_;
  std::vector<SceneEntry> scenes_;  // sorted by effective_tick
  std::map<std::uint64_t, std::shared_ptr<const sim::Frame>> cache_;  // key: tick << 16 | grid, so begin() is the oldest
  std::uint64_t evaluations_ = 0;
  WakeLattice wake_lattice_;
  std::unique_ptr<sim::EpochWake> wake_;
  sim::WakeSampler wake_sampler_;
  sim::Frame wake_part_;
};

}  // namespace ocean::loadtest
