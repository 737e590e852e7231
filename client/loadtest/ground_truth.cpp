#include "ground_truth.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>


namespace ocean::loadtest {

GroundTruth::GroundTruth(int tick_rate_hz, bool choppy, std::size_t cache_frames, std::vector<Cascade> cascades)
    : rate_hz_(tick_rate_hz),
      choppy_(choppy),
      cache_frames_(std::max<std::size_t>(1, cache_frames)),
      cascades_(std::move(cascades)) {
  if (tick_rate_hz < 1) throw std::invalid_argument("GroundTruth: tick_rate_hz must be >= 1, got " + std::to_string(tick_rate_hz));
}

void GroundTruth::set_scene(Tick effective_tick, const protocol::SceneParams& scene) {
  // Already in force at that tick (the usual case: every client reports the same Welcome).
  if (const SceneEntry* current = scene_for(effective_tick); current && current->wire == scene) return;
  auto it = std::find_if(scenes_.begin(), scenes_.end(), [&](const SceneEntry& e) { return e.effective_tick >= effective_tick; });
  if (it != scenes_.end() && it->effective_tick == effective_tick) {
    *it = entry(effective_tick, scene);
  } else {
    scenes_.insert(it, entry(effective_tick, scene));
  }
  // The wake's waves travel at the new depth from that tick on, as the server's do.
  if (wake_) wake_->set_depth(scene.depth_m, static_cast<std::int64_t>(effective_tick));
  forget_from(effective_tick);  // frames from the changed tick on were computed with the old scene
}

GroundTruth::SceneEntry GroundTruth::entry(Tick effective_tick, const protocol::SceneParams& scene) const {
  const model::SceneParams params = scene;
  return SceneEntry{effective_tick, scene, std::make_unique<sim::Ocean>(params),
                    cascades_.empty() ? nullptr : std::make_unique<sim::CascadeSet>(params, cascades_)};
}

GroundTruth::SceneEntry* GroundTruth::scene_for(Tick tick) {
  SceneEntry* found = nullptr;
  for (SceneEntry& e : scenes_)
    if (e.effective_tick <= tick) found = &e;
  // A tick before every known scene (a client joined after a change): the oldest scene known.
  if (!found && !scenes_.empty()) found = &scenes_.front();
  return found;
}

void GroundTruth::set_wake(const WakeLattice& lattice, std::vector<model::VesselTrack> vessels,
                           const protocol::SceneParams& scene) {
  if (lattice.grid == 0) return;  // a wake lattice even with no vessels yet (they may be added live)
  wake_lattice_ = lattice;
  // The stream's own lattice size is enough: a wave below its Nyquist has the same bits in the
  // server's finer field (each mode is stepped alone, from the same wavevector and poses).
  const sim::WakeRegion region{lattice.size_m, lattice.grid, scene.gravity_mps2, scene.depth_m, lattice.decay_per_s,
                               lattice.viscosity_m2ps};
  wake_ = std::make_unique<sim::EpochWake>(region, lattice.origin_x_m, lattice.origin_z_m, std::move(vessels), rate_hz_,
                                           static_cast<std::int64_t>(lattice.epoch_ticks));
  cache_.clear();
}

void GroundTruth::set_vessels(std::vector<model::VesselTrack> vessels, Tick from) {
  if (!wake_ || vessels == wake_->tracks()) return;
  wake_->set_tracks(std::move(vessels), static_cast<std::int64_t>(from));
  forget_from(from);
}

void GroundTruth::forget_from(Tick tick) {
  std::erase_if(cache_, [tick](const auto& entry) { return (entry.first >> 16) >= tick; });
}

double GroundTruth::time_of(Tick tick) const {
  const Tick seconds = tick / static_cast<Tick>(rate_hz_);
  return static_cast<double>(seconds) + static_cast<double>(tick - seconds * rate_hz_) / rate_hz_;
}

std::shared_ptr<const sim::Frame> GroundTruth::at(Tick tick, int grid) {
  const std::uint64_t key = std::uint64_t{tick} << 16 | static_cast<std::uint16_t>(grid);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  SceneEntry* scene = scene_for(tick);
  if (!scene) throw std::logic_error("GroundTruth::at: no scene yet (call set_scene with the Welcome's scene first)");
  while (cache_.size() >= cache_frames_) cache_.erase(cache_.begin());
  auto frame = std::make_shared<sim::Frame>();
  if (scene->cascades)
    scene->cascades->evaluate(time_of(tick), *frame, sim::FrameRequest{true, choppy_});
  else
    scene->ocean->evaluate_band(time_of(tick), grid, grid, *frame, sim::FrameRequest{true, choppy_});
  if (wake_) {
    wake_->advance_to(static_cast<std::int64_t>(tick));
    wake_sampler_.sample(wake_->fields(), wake_lattice_.grid, sim::FrameRequest{true, choppy_}, scene->wire.choppiness,
                         wake_part_);
    sim::append_cascade_frame(*frame, wake_part_);
  }
  ++evaluations_;
  cache_[key] = frame;
  return frame;
}

}  // namespace ocean::loadtest
