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

// The fields both sides hold alike, in one list for both directions; the rest (sizes, enums,
// depth) each direction writes itself.
template <typename From, typename To>
void copy_same_fields(const From& from, To& to) {
  to.patch_x_m = from.patch_x_m;
  to.patch_z_m = from.patch_z_m;
  to.wind_speed_mps = from.wind_speed_mps;
  to.wind_dir_deg = from.wind_dir_deg;
  to.fetch_m = from.fetch_m;
  to.amplitude = from.amplitude;
  to.small_wave_m = from.small_wave_m;
  to.choppiness = from.choppiness;
  to.gravity_mps2 = from.gravity_mps2;
  to.seed = from.seed;
}

}  // namespace

wire::Spectrum to_wire(model::SpectrumKind kind) { return static_cast<wire::Spectrum>(kind); }
wire::Spreading to_wire(model::SpreadingKind kind) { return static_cast<wire::Spreading>(kind); }
model::SpectrumKind to_scene(wire::Spectrum spectrum) { return static_cast<model::SpectrumKind>(spectrum); }
model::SpreadingKind to_scene(wire::Spreading spreading) { return static_cast<model::SpreadingKind>(spreading); }

protocol::SceneParams to_wire(const model::SceneParams& s) {
  protocol::SceneParams w;
  copy_same_fields(s, w);
  w.size_x = static_cast<std::uint16_t>(s.size_x);
  w.size_z = static_cast<std::uint16_t>(s.size_z);
  w.spectrum = to_wire(s.spectrum);
  w.spreading = to_wire(s.spreading);
  w.depth_m = model::wire_depth(s.depth_m);
  return w;
}

model::SceneParams to_scene(const protocol::SceneParams& w) {
  model::SceneParams s;
  copy_same_fields(w, s);
  s.size_x = w.size_x;
  s.size_z = w.size_z;
  s.spectrum = to_scene(w.spectrum);
  s.spreading = to_scene(w.spreading);
  s.depth_m = model::scene_depth(w.depth_m);
  return s;
}

}  // namespace ocean::scene_wire
