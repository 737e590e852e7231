// ModelCache: the scene models and recurrences of one stream, built once for every decoder that
// shares it (a load test's thousands of clients, through their DecodeMemo). Both are pure
// functions of their inputs and used read-only, so sharing them changes no result; building them
// per decoder cost a load test a sixth of its time (det_cos / det_exp per mode, per client).
#pragma once

#include "modal_model.hpp"
#include "scene_model.hpp"
#include "stream_config.hpp"
#include "wake_forcing.hpp"

#include <memory>
#include <vector>

namespace ocean::codec {

class ModelCache {
 public:
  // `stream` already carries the scene's depth (as SceneTimeline builds them).
  std::shared_ptr<const SceneModel> scene_model(const StreamConfig& stream, const model::SceneParams& scene);
  std::shared_ptr<const ModalModel> recurrence(const StreamConfig& stream);
  // The hulls' forcing and the wake's history of one stream's vessels (CODEC.md 7.9), shared by its
  // decoders: they must all follow the same server's timeline (a DecodeMemo's decoders do), since a
  // history is advanced by the recurrences of the scenes in force.
  std::shared_ptr<WakeForcing> wake_forcing(const StreamConfig& stream, const std::vector<model::VesselTrack>& vessels);
  // The same, for a fleet that succeeds `earlier`'s from tick `from` (WakeForcing's successor).
  std::shared_ptr<WakeForcing> wake_forcing(const StreamConfig& stream, const std::vector<model::VesselTrack>& vessels,
                                            const WakeForcing& earlier, Tick from);

 private:
  // Scenes change a few times an hour: a short list, the least recently built dropped first
  // (a timeline that still holds one keeps it alive).
  static constexpr std::size_t kKeep = 8;
  struct SceneEntry {
    StreamConfig stream;
    model::SceneParams scene;
    std::shared_ptr<const SceneModel> model;
  };
  struct RecurrenceEntry {
    StreamConfig stream;
    std::shared_ptr<const ModalModel> model;
  };
  std::vector<SceneEntry> scenes_;
  std::vector<RecurrenceEntry> recurrences_;
  struct ForcingEntry {
    StreamConfig stream;
    std::vector<model::VesselTrack> vessels;
    std::shared_ptr<WakeForcing> model;
  };
  std::vector<ForcingEntry> forcings_;
};

}  // namespace ocean::codec
