#include "fleet_tables.hpp"

#include "param_message.hpp"
#include "wire_limits.hpp"

namespace ocean::server {

std::string at_line(std::string_view source, const toml::node& node) {
  return std::string(source) + ":" + std::to_string(node.source().begin.line);
}

std::optional<double> toml_number(const toml::node* node) {
  if (!node) return std::nullopt;
  if (node->is_floating_point()) return node->as_floating_point()->get();
  if (node->is_integer()) return static_cast<double>(node->as_integer()->get());
  return std::nullopt;
}

namespace {

// An object larger than this is a vessel (its hull presses half its size deep: at most 25 m).

}  // namespace

std::string apply_vessel_tables(ServerConfig& config, const toml::node& node, std::string_view source) {
  const toml::array* entries = node.as_array();
  if (!entries || !entries->is_array_of_tables())
    return at_line(source, node) + ": 'vessel' must be an array of tables ([[vessel]])";
  config.vessels.clear();
  std::size_t index = 0;
  for (const toml::node& entry_node : *entries) {
    const toml::table& t = *entry_node.as_table();
    const std::string where = at_line(source, entry_node) + ": vessel " + std::to_string(++index);
    for (auto&& [key, value] : t)
      if (key.str() != "id" && key.str() != "length" && key.str() != "beam" && key.str() != "draft" &&
          key.str() != "repeat" && key.str() != "waypoints")
        return where + ": unknown key '" + std::string(key.str()) + "' (id, length, beam, draft, repeat, waypoints)";
    model::VesselTrack v;
    const toml::node* id = t.get("id");
    if (!id || !id->is_integer() || id->as_integer()->get() < 0 || id->as_integer()->get() > 0xffffffffLL)
      return where + ": needs id = N (an integer in 0..4294967295)";
    v.id = static_cast<std::uint32_t>(id->as_integer()->get());
    const auto length = toml_number(t.get("length")), beam = toml_number(t.get("beam")), draft = toml_number(t.get("draft"));
    if (!length || !beam || !draft) return where + ": needs length, beam and draft (numbers, metres)";
    v.hull = {*length, *beam, *draft};
    if (const toml::node* repeat = t.get("repeat")) {
      if (!repeat->is_boolean()) return where + ": repeat must be true or false";
      v.repeat = repeat->as_boolean()->get();
    }
    const toml::array* points = t.get("waypoints") ? t.get("waypoints")->as_array() : nullptr;
    if (!points || points->empty()) return where + ": needs waypoints = [[t, x, z], ...] (at least one)";
    if (points->size() > protocol::kMaxWaypoints)
      return where + ": " + std::to_string(points->size()) + " waypoints; at most " + std::to_string(protocol::kMaxWaypoints);
    for (const toml::node& p : *points) {
      const toml::array* xyz = p.as_array();
      const auto time = xyz && xyz->size() == 3 ? toml_number(xyz->get(0)) : std::nullopt;
      const auto x = xyz && xyz->size() == 3 ? toml_number(xyz->get(1)) : std::nullopt;
      const auto z = xyz && xyz->size() == 3 ? toml_number(xyz->get(2)) : std::nullopt;
      if (!time || !x || !z) return where + ": each waypoint is [t, x, z] (three numbers: seconds, metres, metres)";
      v.points.push_back({*time, *x, *z});
    }
    if (config.vessels.size() == protocol::kMaxVessels)
      return where + ": more than " + std::to_string(protocol::kMaxVessels) + " vessels";
    config.vessels.push_back(std::move(v));
  }
  return {};
}

// [[drop]]: a round hull of the object's size, pressing half its size deep for `splash` seconds
// from `at`, again every `every` seconds when that is > 0 (model::Presence), where it fell.
std::string apply_drop_tables(const toml::node& node, std::string_view source, std::vector<model::VesselTrack>& drops) {
  const toml::array* entries = node.as_array();
  if (!entries || !entries->is_array_of_tables())
    return at_line(source, node) + ": 'drop' must be an array of tables ([[drop]])";
  drops.clear();
  std::size_t index = 0;
  for (const toml::node& entry_node : *entries) {
    const toml::table& t = *entry_node.as_table();
    const std::string where = at_line(source, entry_node) + ": drop " + std::to_string(++index);
    for (auto&& [key, value] : t)
      if (key.str() != "id" && key.str() != "x" && key.str() != "z" && key.str() != "size" && key.str() != "at" &&
          key.str() != "splash" && key.str() != "every")
        return where + ": unknown key '" + std::string(key.str()) + "' (id, x, z, size, at, splash, every)";
    const toml::node* id = t.get("id");
    if (!id || !id->is_integer() || id->as_integer()->get() < 0 || id->as_integer()->get() > 0xffffffffLL)
      return where + ": needs id = N (an integer in 0..4294967295)";
    const auto x = toml_number(t.get("x")), z = toml_number(t.get("z"));
    if (!x || !z) return where + ": needs x and z (numbers, world metres)";
    const auto number_or = [&](const char* key, double fallback) -> std::optional<double> {
      return t.get(key) ? toml_number(t.get(key)) : std::optional<double>(fallback);
    };
    const auto size = number_or("size", 2.0), at = number_or("at", 0.0), splash = number_or("splash", 1.0),
               every = number_or("every", 0.0);
    if (!size || !at || !splash || !every) return where + ": size, at, splash and every are numbers (metres, seconds)";
    if (!(*size > 0.0 && *size <= kMaxDropSizeM))
      return where + ": size " + model::format_value(*size) + ": must be in (0, " + model::format_value(kMaxDropSizeM) + "] metres";
    if (drops.size() == protocol::kMaxVessels)
      return where + ": more than " + std::to_string(protocol::kMaxVessels) + " objects";
    drops.push_back(dropped_object(static_cast<std::uint32_t>(id->as_integer()->get()), *size, *x, *z, {*at, *splash, *every}));
  }
  return {};
}

}  // namespace ocean::server
