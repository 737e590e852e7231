#include "scene_wire.hpp"

#include <cstddef>

#include "scene_names.hpp"

namespace ocean::scene_wire {
namespace {

// The enums are cast, so every enumerator must have one value on both sides. A spectrum added to
// the model (its name table) but not to ocean.fbs, or the other way round, stops the build here.
template <typename Kind, std::size_t N>
constexpr bool in_enum_order(const model::Named<Kind> (&table)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(table[i].kind) != i) return false;
  return true;
}

static_assert(in_enum_order(model::kSpectra) && in_enum_order(model::kSpreadings));
static_assert(std::size(model::kSpectra) == static_cast<std::size_t>(wire::Spectrum::MAX) + 1);
static_assert(std::size(model::kSpreadings) == static_cast<std::size_t>(wire::Spreading::MAX) + 1);
static_assert(static_cast<int>(wire::Spectrum::phillips) == static_cast<int>(model::SpectrumKind::phillips));
static_assert(static_cast<int>(wire::Spectrum::jonswap) == static_cast<int>(model::SpectrumKind::jonswap));
static_assert(static_cast<int>(wire::Spreading::cos2s) == static_cast<int>(model::SpreadingKind::cos2s));
static_assert(static_cast<int>(wire::Spreading::donelan_banner) == static_cast<int>(model::SpreadingKind::donelan_banner));
static_assert(static_cast<int>(wire::Spreading::hasselmann) == static_cast<int>(model::SpreadingKind::hasselmann));

}  // namespace

wire::Spectrum to_wire(model::SpectrumKind kind) { return static_cast<wire::Spectrum>(kind); }
wire::Spreading to_wire(model::SpreadingKind kind) { return static_cast<wire::Spreading>(kind); }
model::SpectrumKind to_scene(wire::Spectrum spectrum) { return static_cast<model::SpectrumKind>(spectrum); }
model::SpreadingKind to_scene(wire::Spreading spreading) { return static_cast<model::SpreadingKind>(spreading); }

}  // namespace ocean::scene_wire
