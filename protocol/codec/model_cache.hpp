// ModelCache: the scene models and recurrences of one stream, built once for every decoder that
// shares it (a load test's thousands of clients, through their DecodeMemo). Both are pure
// functions of their inputs and used read-only, so sharing them changes no result; building them
// per decoder cost a load test a sixth of its time (det_cos / det_exp per mode, per client).
#pragma once

#include "modal_model.hpp"
#include "scene_model.hpp"
#include "stream_config.hpp"

#include <memory>
#include <vector>

namespace ocean::codec {

class ModelCache {
 public:
  // `stream` already carries the scene's depth (as SceneTimeline builds them).
  std::shared_ptr<const SceneModel> scene_model(const StreamConfig& stream, const model::SceneParams& scene);
  std::shared_ptr<const ModalModel> recurrence(const StreamConfig& stream);

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
};

}  // namespace ocean::codec
