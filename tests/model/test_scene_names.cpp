// The spectrum and spreading name tables: both directions agree, the lists are in enum order, and
// unknown names or values are refused rather than mapped to a default.
#include <catch2/catch.hpp>

#include "scene_names.hpp"

using namespace ocean::model;

namespace {

// Every listed name maps to the enum value of its index, and back to itself.
template <typename Kind>
void check_round_trip(const std::vector<std::string>& names, std::optional<Kind> (*from_name)(std::string_view),
                      std::string_view (*to_name)(Kind)) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    CAPTURE(names[i]);
    const std::optional<Kind> kind = from_name(names[i]);
    REQUIRE(kind);
    CHECK(static_cast<std::size_t>(*kind) == i);
    CHECK(to_name(*kind) == names[i]);
  }
}

}  // namespace

TEST_CASE("spectrum names map to kinds and back, in enum order") {
  REQUIRE(spectrum_names() == std::vector<std::string>{"phillips", "jonswap"});
  check_round_trip(spectrum_names(), spectrum_from_name, spectrum_name);
  CHECK_FALSE(spectrum_from_name("Phillips"));
  CHECK_FALSE(spectrum_from_name(""));
  CHECK(spectrum_name(static_cast<SpectrumKind>(7)).empty());
}

TEST_CASE("spreading names map to kinds and back, in enum order") {
  REQUIRE(spreading_names() == std::vector<std::string>{"cos2s", "donelan-banner", "hasselmann"});
  check_round_trip(spreading_names(), spreading_from_name, spreading_name);
  CHECK_FALSE(spreading_from_name("donelan_banner"));
  CHECK(spreading_name(static_cast<SpreadingKind>(9)).empty());
}

TEST_CASE("join_names writes the lists for help and messages") {
  CHECK(join_names(spreading_names()) == "cos2s, donelan-banner, hasselmann");
  CHECK(join_names(spreading_names(), ", ", " or ") == "cos2s, donelan-banner or hasselmann");
  CHECK(join_names(spectrum_names(), "|", "|") == "phillips|jonswap");
  CHECK(join_names({"one"}, ", ", " or ") == "one");
  CHECK(join_names({}).empty());
}
