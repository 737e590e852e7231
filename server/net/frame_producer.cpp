#include "frame_producer.hpp"

#include <mutex>

namespace ocean::server {
namespace {

constexpr std::size_t kMaxPooledBuffers = 8;

}  // namespace

struct FrameProducer::BufferPool {
  BufferPool() { free.reserve(kMaxPooledBuffers); }  // so giving a buffer back never allocates
  std::mutex mutex;  // also orders the network thread's last reads before the next tick's writes
  std::vector<std::unique_ptr<TickFrames>> free;
};

FrameProducer::FrameProducer(SceneSchedule schedule, std::vector<const Profile*> profiles)
    : schedule_(std::move(schedule)),
      profiles_(std::move(profiles)),
      scheduled_scene_(&schedule_.base()),
      pool_(std::make_shared<BufferPool>()) {
  use_scene(*scheduled_scene_);
}

void FrameProducer::use_scene(const sim::SceneParams& scene) {
  ocean_ = std::make_unique<sim::Ocean>(scene);
  cascades_.clear();
  for (const Profile* profile : profiles_)
    cascades_.push_back(profile->cascades.empty() ? nullptr : std::make_unique<sim::CascadeSet>(scene, profile->cascades));
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
  const sim::SceneParams& scheduled = schedule_.scene_at(tick);
  scene_changed_ = false;
  if (&scheduled != scheduled_scene_) {
    scheduled_scene_ = &scheduled;
    use_scene(scheduled);
    scene_changed_ = true;
  }
  if (!overrides_.empty() && overrides_.begin()->first <= tick) {
    const auto due = overrides_.upper_bound(tick);
    use_scene(std::prev(due)->second);
    overrides_.erase(overrides_.begin(), due);
    scene_changed_ = true;
  }

  std::shared_ptr<TickFrames> result = take_buffer();
  result->tick = tick;
  result->time_s = time_s;
  result->scene = ocean_->params();
  result->scene_changed = scene_changed_;
  result->frames.resize(profiles_.size());
  for (std::size_t i = 0; i < profiles_.size(); ++i) {
    const Profile& profile = *profiles_[i];
    result->frames[i].profile = &profile;
    if (cascades_[i]) {
      cascades_[i]->evaluate(time_s, result->frames[i].frame, sim::FrameRequest{profile.normals, profile.choppy});
      continue;
    }
    ocean_->evaluate_band(time_s, profile.grid, profile.grid, result->frames[i].frame,
                          sim::FrameRequest{profile.normals, profile.choppy});
  }
  return result;
}

}  // namespace ocean::server
