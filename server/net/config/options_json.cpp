#include "options_json.hpp"

#include "common/json_writer.hpp"
#include "config_options.hpp"
#include "profile.hpp"

namespace ocean::server {
namespace {

std::string_view kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::integer: return "integer";
    case ValueKind::number: return "number";
    case ValueKind::number_or_text: return "number_or_text";
    case ValueKind::text: return "text";
    case ValueKind::text_list: return "text_list";
    case ValueKind::integer_or_text: return "integer_or_text";
  }
  return "text";
}

std::string array(const std::string& items) { return "[" + items + "]"; }

}  // namespace

std::string options_json() {
  using common::JsonWriter;
  const ServerConfig defaults;
  std::string options;
  for (const ConfigOption& option : config_options()) {
    if (!options.empty()) options += ", ";
    options += JsonWriter()
                   .text("name", option.name)
                   .text("value_name", option.value_name)
                   .text("help", option.help)
                   .text("kind", kind_name(option.kind))
                   .boolean("schedulable", option.schedulable)
                   .text("default", option.show(defaults))
                   .str();
  }
  std::string profiles;
  for (const Profile& profile : all_profiles()) {
    if (!profiles.empty()) profiles += ", ";
    profiles += JsonWriter()
                    .integer("id", static_cast<int>(profile.id))
                    .text("name", profile.name)
                    .integer("grid", static_cast<int>(profile.grid))
                    .integer("rate_hz", static_cast<int>(profile.rate_hz))
                    .boolean("normals", profile.normals)
                    .boolean("choppy", profile.choppy)
                    .str();
  }
  return JsonWriter().raw("options", array(options)).raw("profiles", array(profiles)).str() + "\n";
}

}  // namespace ocean::server
