#include "sea_state.hpp"

namespace ocean::server {

SeaState SeaBuilder::build(const model::SceneParams& scene) const {
  SeaState sea;
  sea.ocean = std::make_unique<sim::Ocean>(scene);
  for (std::size_t i = 0; i < profiles_.size(); ++i) {
    const Profile& profile = *profiles_[i];
    const bool evaluated = !profile.cascades.empty() && cascade_source_[i] == i;
    sea.cascades.push_back(evaluated ? std::make_unique<sim::CascadeSet>(scene, profile.cascades) : nullptr);
    if (profile.cascades.empty()) sea.ocean->prepare_band(profile.grid, profile.grid);
  }
  return sea;
}

std::future<SeaState> SeaBuilder::build_ahead(BuildQueue& queue, const model::SceneParams& scene) const {
  return queue.submit([builder = *this, scene] { return builder.build(scene); });
}

}  // namespace ocean::server
