#include "scene_json.hpp"

#include "common/json_writer.hpp"
#include "scene_wire.hpp"

namespace ocean::admin {

std::string scene_json(const protocol::SceneParams& s) {
  common::JsonWriter json(common::JsonWriter::Style::compact);
  // As the wire names and carries them: the schema's enum names, deep water 0.
  json.text("spectrum", wire::EnumNameSpectrum(scene_wire::to_wire(s.spectrum)))
      .text("spreading", wire::EnumNameSpreading(scene_wire::to_wire(s.spreading)));
  json.number("wind_speed_mps", s.wind_speed_mps, 17).number("wind_dir_deg", s.wind_dir_deg, 17);
  json.number("amplitude", s.amplitude, 17).number("choppiness", s.choppiness, 17);
  json.number("fetch_m", s.fetch_m, 17).number("depth_m", model::wire_depth(s.depth_m), 17).number("small_wave_m", s.small_wave_m, 17);
  json.integer("size_x", s.size_x).integer("size_z", s.size_z);
  json.number("patch_x_m", s.patch_x_m, 17).number("patch_z_m", s.patch_z_m, 17);
  json.number("gravity_mps2", s.gravity_mps2, 17).integer("seed", s.seed);
  return json.str();
}

}  // namespace ocean::admin
