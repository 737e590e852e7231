// The names people type for the scene's enums (--spectrum jonswap, spreading = "cos2s"), in one
// table each: name <-> enum both ways, and the list of valid names for help and error messages.
// Every front end (ocean-server's options and config file, ocean-simdump) goes through these.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene_params.hpp"

namespace ocean::model {

template <typename Kind>
struct Named {
  Kind kind;
  std::string_view name;
};

// In enum order, one row per enumerator: a new enum value gets its name here and nowhere else.
// Visible at compile time so the wire mapping (protocol/scene_wire) can assert it covers them all.
inline constexpr Named<SpectrumKind> kSpectra[] = {
    {SpectrumKind::phillips, "phillips"},
    {SpectrumKind::jonswap, "jonswap"},
};

inline constexpr Named<SpreadingKind> kSpreadings[] = {
    {SpreadingKind::cos2s, "cos2s"},
    {SpreadingKind::donelan_banner, "donelan-banner"},
    {SpreadingKind::hasselmann, "hasselmann"},
};

// "phillips", "jonswap"; empty for a value outside the enum.
std::string_view spectrum_name(SpectrumKind kind);
// "cos2s", "donelan-banner", "hasselmann"; empty for a value outside the enum.
std::string_view spreading_name(SpreadingKind kind);

std::optional<SpectrumKind> spectrum_from_name(std::string_view name);
std::optional<SpreadingKind> spreading_from_name(std::string_view name);

// The valid names in enum order (a value's index is its enum value).
std::vector<std::string> spectrum_names();
std::vector<std::string> spreading_names();

// Joins names for messages and help: ({"a", "b", "c"}, ", ", " or ") -> "a, b or c".
std::string join_names(const std::vector<std::string>& names, std::string_view separator = ", ",
                       std::string_view last_separator = ", ");

}  // namespace ocean::model
