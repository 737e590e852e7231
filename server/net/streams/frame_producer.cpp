#include "frame_producer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <utility>

namespace ocean::server {
namespace {

constexpr std::size_t kMaxPooledBuffers = 8;

sim::FrameRequest request_of(const Profile& profile) { return {profile.normals, profile.choppy}; }

// Empties the fields `request` does not name (capacity kept for the next tick).
void keep_requested(sim::Frame& f, sim::FrameRequest request) {
  for (std::size_t i = 0; i < sim::kFrameFields.size(); ++i)
    if (!sim::requested(i, request)) (f.*sim::kFrameFields[i]).clear();
}

// The fields `request` names, from a frame evaluated with at least those.
void copy_requested(const sim::Frame& from, sim::Frame& to, sim::FrameRequest request) {
  to.n_x = from.n_x;
  to.n_z = from.n_z;
  to.patch_x_m = from.patch_x_m;
  to.patch_z_m = from.patch_z_m;
  to.time_s = from.time_s;
  for (std::size_t i = 0; i < sim::kFrameFields.size(); ++i)
    if (sim::requested(i, request)) to.*sim::kFrameFields[i] = from.*sim::kFrameFields[i];
  keep_requested(to, request);
}

}  // namespace

struct FrameProducer::BufferPool {
  BufferPool() { free.reserve(kMaxPooledBuffers); }  // so giving a buffer back never allocates
  std::mutex mutex;  // also orders the network thread's last reads before the next tick's writes
  std::vector<std::unique_ptr<TickFrames>> free;
};

FrameProducer::FrameProducer(SceneSchedule schedule, std::vector<const Profile*> profiles, const WakeSetup& wake)
    : schedule_(std::move(schedule)),
      profiles_(std::move(profiles)),
      scheduled_scene_(&schedule_.base()),
      pool_(std::make_shared<BufferPool>()) {
  if (wake.always || !wake.vessels.empty()) {
    // One field fine enough for every profile's lattice; each samples the waves below its Nyquist.
    int n = 16;
    for (const Profile* p : profiles_) n = std::max<int>(n, p->wake_grid);
    const sim::WakeRegion region{wake.size_m, n, schedule_.base().gravity_mps2, schedule_.base().depth_m, wake.decay_per_s, 1e-6};
    wake_ = std::make_unique<sim::EpochWake>(region, wake.origin_x_m, wake.origin_z_m, wake.vessels, wake.tick_rate_hz,
                                             sim::wake_epoch_ticks(wake.tick_rate_hz));
    // The wake's waves travel at the depth of the scene in force at each tick, as the codec's do.
    for (const ScheduledScene& change : schedule_.changes()) wake_->set_depth(change.scene.depth_m, change.tick);
  }
  // Profiles with the same cascades (desktop and desktop-choppy) share one evaluation, with every
  // channel either streams: the sim's channels are transforms of their own, so each profile's
  // are the bits it would get alone.
  for (std::size_t i = 0; i < profiles_.size(); ++i) {
    std::size_t source = i;
    for (std::size_t j = 0; j < i && source == i; ++j)
      if (!profiles_[i]->cascades.empty() && std::ranges::equal(profiles_[j]->cascades, profiles_[i]->cascades))
        source = cascade_source_[j];
    cascade_source_.push_back(source);
    cascade_request_.push_back(request_of(*profiles_[i]));
    sim::FrameRequest& shared = cascade_request_[source];
    shared.slopes = shared.slopes || profiles_[i]->normals;
    shared.choppy = shared.choppy || profiles_[i]->choppy;
  }
  builder_ = std::make_unique<SeaBuilder>(profiles_, cascade_source_);
  use_sea(builder_->build(*scheduled_scene_));
}

// The old sea's plans are destroyed on the build queue, off the tick (destroying a plan takes FFTW's
// planner lock).
void FrameProducer::use_sea(SeaState sea) {
  auto old = std::make_shared<SeaState>(std::exchange(sea_, std::move(sea)));
  if (old->ocean) (void)builds_.submit([old]() mutable { old.reset(); });
}

void FrameProducer::override_scene(const model::SceneParams& scene, std::int64_t from) {
  ++requests_taken_;
  overrides_[from] = builder_->build_ahead(builds_, scene);
  if (wake_) wake_->set_depth(scene.depth_m, from);
}

void FrameProducer::build_next_scheduled(std::int64_t tick) {
  const auto next = std::ranges::upper_bound(schedule_.changes(), tick, {}, &ScheduledScene::tick);
  if (next == schedule_.changes().end() || next->tick - tick > kScheduleLookaheadTicks) return;
  if (next_scheduled_.scene == &next->scene) return;
  next_scheduled_ = PendingSea{&next->scene, builder_->build_ahead(builds_, next->scene)};
}

std::shared_ptr<TickFrames> FrameProducer::take_buffer() {
  std::unique_ptr<TickFrames> buffer;
  {
    std::lock_guard lock(pool_->mutex);
    if (!pool_->free.empty()) {
      buffer = std::move(pool_->free.back());
      pool_->free.pop_back();
    }
  }
  if (!buffer) buffer = std::make_unique<TickFrames>();
  return std::shared_ptr<TickFrames>(buffer.release(), [pool = pool_](TickFrames* frames) {
    std::unique_ptr<TickFrames> owned(frames);
    std::lock_guard lock(pool->mutex);
    if (pool->free.size() < kMaxPooledBuffers) pool->free.push_back(std::move(owned));
  });
}

std::shared_ptr<const TickFrames> FrameProducer::produce(std::int64_t tick, double time_s) {
  const model::SceneParams& scheduled = schedule_.scene_at(tick);
  scene_changed_ = false;
  if (&scheduled != scheduled_scene_) {
    scheduled_scene_ = &scheduled;
    // Built ahead unless the producer started (or jumped) within the lookahead of it. A build not
    // finished by its tick is waited for: it is under way at the tick's priority, and the rest of
    // it costs the tick no more than building it here would.
    use_sea(next_scheduled_.scene == &scheduled ? next_scheduled_.sea.get() : builder_->build(scheduled));
    next_scheduled_ = {};
    scene_changed_ = true;
  }
  build_next_scheduled(tick);
  if (!overrides_.empty() && overrides_.begin()->first <= tick) {
    const auto due = overrides_.upper_bound(tick);
    use_sea(std::prev(due)->second.get());
    overrides_.erase(overrides_.begin(), due);
    scene_changed_ = true;
  }

  std::shared_ptr<TickFrames> result = take_buffer();
  result->tick = tick;
  result->time_s = time_s;
  result->scene = ocean().params();
  result->scene_changed = scene_changed_;
  result->requests_taken = requests_taken_;
  result->frames.resize(profiles_.size());
  for (std::size_t i = 0; i < profiles_.size(); ++i) {
    const Profile& profile = *profiles_[i];
    result->frames[i].profile = &profile;
    if (sea_.cascades[i]) {
      sea_.cascades[i]->evaluate(time_s, result->frames[i].frame, cascade_request_[i]);
      continue;
    }
    if (!profile.cascades.empty()) continue;  // shares an evaluation: below
    sea_.ocean->evaluate_band(time_s, profile.grid, profile.grid, result->frames[i].frame, request_of(profile));
  }
  for (std::size_t i = 0; i < profiles_.size(); ++i)
    if (cascade_source_[i] != i)
      copy_requested(result->frames[cascade_source_[i]].frame, result->frames[i].frame, request_of(*profiles_[i]));
  // A shared evaluation may hold channels its own profile does not stream.
  for (std::size_t i = 0; i < profiles_.size(); ++i)
    if (sea_.cascades[i]) keep_requested(result->frames[i].frame, request_of(*profiles_[i]));
  if (wake_) {
    wake_->advance_to(tick);
    const std::vector<const sim::WakeField*> fields = wake_->fields();
    for (std::size_t i = 0; i < profiles_.size(); ++i) {
      wake_sampler_.sample(fields, profiles_[i]->wake_grid, request_of(*profiles_[i]), ocean().params().choppiness, wake_part_);
      sim::append_cascade_frame(result->frames[i].frame, wake_part_);
    }
  }
  return result;
}

}  // namespace ocean::server
