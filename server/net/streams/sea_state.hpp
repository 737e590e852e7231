// SeaState: the simulation's objects for one scene - its Ocean (with every offered profile's band
// built) and the cascades of each cascaded profile. Building one draws every mode's amplitude and
// plans the transforms: tens of milliseconds for a server of every profile, too long for the tick
// a scene starts at. So a scene known ahead (an admin change a lead before its tick, the schedule's
// next entry) is built on the server's BuildQueue meanwhile, and the tick only swaps it in.
#pragma once

#include "build_queue.hpp"
#include "cascade_set.hpp"
#include "ocean.hpp"
#include "profile.hpp"
#include "scene_params.hpp"

#include <future>
#include <memory>
#include <vector>

namespace ocean::server {

struct SeaState {
  std::unique_ptr<sim::Ocean> ocean;
  // Per offered profile: its cascades' Oceans, or null (no cascades, or it shares an earlier one's).
  std::vector<std::unique_ptr<sim::CascadeSet>> cascades;
};

// Builds SeaStates for one server's profiles. A value: a build ahead holds its own copy, so it
// outlives nothing it reads.
class SeaBuilder {
 public:
  // cascade_source[i]: the profile whose cascade evaluation profile i uses (i itself if its own).
  SeaBuilder(std::vector<const Profile*> profiles, std::vector<std::size_t> cascade_source)
      : profiles_(std::move(profiles)), cascade_source_(std::move(cascade_source)) {}

  // Throws model::ParamError for a scene the sim cannot evaluate.
  SeaState build(const model::SceneParams& scene) const;
  // The same, on `queue`; get() rethrows what build threw.
  std::future<SeaState> build_ahead(BuildQueue& queue, const model::SceneParams& scene) const;

 private:
  std::vector<const Profile*> profiles_;
  std::vector<std::size_t> cascade_source_;
};

}  // namespace ocean::server
