#include "model_cache.hpp"

namespace ocean::codec {
namespace {

template <typename Entries, typename Same, typename Build>
auto find_or_build(Entries& entries, std::size_t keep, Same same, Build build) {
  for (const auto& e : entries)
    if (same(e)) return e.model;
  if (entries.size() >= keep) entries.erase(entries.begin());
  entries.push_back(build());
  return entries.back().model;
}

}  // namespace

std::shared_ptr<const SceneModel> ModelCache::scene_model(const StreamConfig& stream, const model::SceneParams& scene) {
  // Choppiness does not shape heights: scenes differing only in it share one model.
  model::SceneParams heights = scene;
  heights.choppiness = 0.0;
  return find_or_build(
      scenes_, kKeep, [&](const SceneEntry& e) { return e.stream == stream && e.scene == heights; },
      [&] { return SceneEntry{stream, heights, std::make_shared<const SceneModel>(stream, heights)}; });
}

std::shared_ptr<const ModalModel> ModelCache::recurrence(const StreamConfig& stream) {
  return find_or_build(
      recurrences_, kKeep, [&](const RecurrenceEntry& e) { return e.stream == stream; },
      [&] { return RecurrenceEntry{stream, std::make_shared<const ModalModel>(stream)}; });
}

std::shared_ptr<WakeForcing> ModelCache::wake_forcing(const StreamConfig& stream,
                                                     const std::vector<model::VesselTrack>& vessels) {
  return find_or_build(
      forcings_, kKeep, [&](const ForcingEntry& e) { return e.stream == stream && e.vessels == vessels; },
      [&] { return ForcingEntry{stream, vessels, std::make_shared<WakeForcing>(stream, vessels)}; });
}

std::shared_ptr<WakeForcing> ModelCache::wake_forcing(const StreamConfig& stream,
                                                     const std::vector<model::VesselTrack>& vessels,
                                                     const WakeForcing& earlier, Tick from) {
  return find_or_build(
      forcings_, kKeep, [&](const ForcingEntry& e) { return e.stream == stream && e.vessels == vessels; },
      [&] { return ForcingEntry{stream, vessels, std::make_shared<WakeForcing>(earlier, vessels, from)}; });
}

}  // namespace ocean::codec
