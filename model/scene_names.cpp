// Look-ups in the spectrum and spreading name tables (scene_names.hpp).
#include "scene_names.hpp"

namespace ocean::model {
namespace {

template <typename Kind, std::size_t N>
std::string_view name_in(const Named<Kind> (&table)[N], Kind kind) {
  for (const Named<Kind>& entry : table)
    if (entry.kind == kind) return entry.name;
  return {};
}

template <typename Kind, std::size_t N>
std::optional<Kind> kind_in(const Named<Kind> (&table)[N], std::string_view name) {
  for (const Named<Kind>& entry : table)
    if (entry.name == name) return entry.kind;
  return std::nullopt;
}

template <typename Kind, std::size_t N>
std::vector<std::string> names_in(const Named<Kind> (&table)[N]) {
  std::vector<std::string> names;
  for (const Named<Kind>& entry : table) names.emplace_back(entry.name);
  return names;
}

}  // namespace

std::string_view spectrum_name(SpectrumKind kind) { return name_in(kSpectra, kind); }
std::string_view spreading_name(SpreadingKind kind) { return name_in(kSpreadings, kind); }

std::optional<SpectrumKind> spectrum_from_name(std::string_view name) { return kind_in(kSpectra, name); }
std::optional<SpreadingKind> spreading_from_name(std::string_view name) { return kind_in(kSpreadings, name); }

std::vector<std::string> spectrum_names() { return names_in(kSpectra); }
std::vector<std::string> spreading_names() { return names_in(kSpreadings); }

std::string join_names(const std::vector<std::string>& names, std::string_view separator,
                       std::string_view last_separator) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? last_separator : separator;
    out += names[i];
  }
  return out;
}

}  // namespace ocean::model
