// FrameProducer: the simulation thread's work per tick. Evaluates the ocean for every offered
// profile at the tick's time, switching scenes when the schedule says so. No clock, no I/O:
// the tick and its time are arguments, so it is tested like the simulation itself.
#pragma once

#include "epoch_wake.hpp"
#include "wake_frame.hpp"
#include "scene_schedule.hpp"
#include "sea_state.hpp"
#include "tick_frames.hpp"

#include <memory>
#include <map>
#include <optional>
#include <vector>

namespace ocean::server {

// The vessels and the square of the world where their wake is simulated (CODEC.md 7.9).
struct WakeSetup {
  double size_m = 512.0, origin_x_m = -256.0, origin_z_m = -256.0;
  double decay_per_s = 0.05;
  std::vector<model::VesselTrack> vessels;
  int tick_rate_hz = 30;
  bool always = false;  // a wake even with no vessels (they may be added live)
};

class FrameProducer {
 public:
  // Profiles must fit the scene (validate_server_config checks it). Throws model::ParamError.
  // With vessels, every profile's frame ends with the wake lattice of its wake_grid.
  FrameProducer(SceneSchedule schedule, std::vector<const Profile*> profiles, const WakeSetup& wake = {});
  FrameProducer(const FrameProducer&) = delete;  // active_scene_ points into schedule_
  FrameProducer& operator=(const FrameProducer&) = delete;

  // The frames for `tick` at `time_s`. A result's buffers return to a pool when the last reference
  // to it is dropped (on any thread), so a steady state allocates nothing.
  std::shared_ptr<const TickFrames> produce(std::int64_t tick, double time_s);

  // From tick `from` on, this scene replaces the active one (an admin change); it lasts
  // until the schedule reaches its next entry. The scene must pass model::validate.
  // Several may wait (admin changes within one announcement lead), each from its own tick.
  // Its sea is built meanwhile on the producer's BuildQueue.
  void override_scene(const model::SceneParams& scene, std::int64_t from);
  // A vessel command: the fleet from tick `from` on (its presences agree with the current fleet's
  // before it). Ignored without a wake (the server was started without vessels).
  void set_vessels(std::vector<model::VesselTrack> vessels, std::int64_t from) {
    ++requests_taken_;
    if (wake_) wake_->set_tracks(std::move(vessels), from);
  }
  // True when the last produce() switched to a scheduled or overriding scene.
  bool scene_changed() const { return scene_changed_; }
  const model::SceneParams& scene() const { return ocean().params(); }

 private:
  struct BufferPool;  // shared with every result's deleter, which returns the buffer to it
  std::shared_ptr<TickFrames> take_buffer();

  struct PendingSea {
    const model::SceneParams* scene = nullptr;
    std::future<SeaState> sea;
  };
  // The schedule's next entry, built ahead once it is this close.
  static constexpr std::int64_t kScheduleLookaheadTicks = 60;
  void build_next_scheduled(std::int64_t tick);
  void use_sea(SeaState sea);
  const sim::Ocean& ocean() const { return *sea_.ocean; }

  SceneSchedule schedule_;
  std::vector<const Profile*> profiles_;
  const model::SceneParams* scheduled_scene_;  // the schedule entry last applied
  // Per offered profile, the first with its cascades (itself if none before it has them), and the
  // channels an evaluation there makes: every channel of the profiles sharing it.
  std::vector<std::size_t> cascade_source_;
  std::vector<sim::FrameRequest> cascade_request_;
  std::unique_ptr<SeaBuilder> builder_;
  BuildQueue builds_;
  // The scene in force: a cascaded profile's frame is its cascades' frames one after the other.
  SeaState sea_;
  // Admin changes' seas, by first tick (a superseded one's build runs on, unused).
  std::map<std::int64_t, std::future<SeaState>> overrides_;
  PendingSea next_scheduled_;
  std::shared_ptr<BufferPool> pool_;
  bool scene_changed_ = false;
  std::uint64_t requests_taken_ = 0;  // override_scene and set_vessels calls (TickFrames::requests_taken)
  std::unique_ptr<sim::EpochWake> wake_;  // none without vessels
  sim::WakeSampler wake_sampler_;
  sim::Frame wake_part_;
};

}  // namespace ocean::server
