#include "scene_wire.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include "scene_names.hpp"

namespace ocean::scene_wire {
namespace {

// The enums are cast, so every enumerator must have one value on both sides. A spectrum added to
// the sim (its name table) but not to ocean.fbs, or the other way round, stops the build here.
template <typename Kind, std::size_t N>
constexpr bool in_enum_order(const sim::Named<Kind> (&table)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(table[i].kind) != i) return false;
  return true;
}

static_assert(in_enum_order(sim::kSpectra) && in_enum_order(sim::kSpreadings));
static_assert(std::size(sim::kSpectra) == static_cast<std::size_t>(wire::Spectrum::MAX) + 1);
static_assert(std::size(sim::kSpreadings) == static_cast<std::size_t>(wire::Spreading::MAX) + 1);
static_assert(static_cast<int>(wire::Spectrum::phillips) == static_cast<int>(sim::SpectrumKind::phillips));
static_assert(static_cast<int>(wire::Spectrum::jonswap) == static_cast<int>(sim::SpectrumKind::jonswap));
static_assert(static_cast<int>(wire::Spreading::cos2s) == static_cast<int>(sim::SpreadingKind::cos2s));
static_assert(static_cast<int>(wire::Spreading::donelan_banner) == static_cast<int>(sim::SpreadingKind::donelan_banner));
static_assert(static_cast<int>(wire::Spreading::hasselmann) == static_cast<int>(sim::SpreadingKind::hasselmann));

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

double wire_depth(double sim_depth_m) { return std::isinf(sim_depth_m) ? 0.0 : sim_depth_m; }
double sim_depth(double wire_depth_m) {
  return wire_depth_m == 0.0 ? std::numeric_limits<double>::infinity() : wire_depth_m;
}

wire::Spectrum to_wire(sim::SpectrumKind kind) { return static_cast<wire::Spectrum>(kind); }
wire::Spreading to_wire(sim::SpreadingKind kind) { return static_cast<wire::Spreading>(kind); }
sim::SpectrumKind to_sim(wire::Spectrum spectrum) { return static_cast<sim::SpectrumKind>(spectrum); }
sim::SpreadingKind to_sim(wire::Spreading spreading) { return static_cast<sim::SpreadingKind>(spreading); }

protocol::SceneParams to_wire(const sim::SceneParams& s) {
  protocol::SceneParams w;
  copy_same_fields(s, w);
  w.size_x = static_cast<std::uint16_t>(s.size_x);
  w.size_z = static_cast<std::uint16_t>(s.size_z);
  w.spectrum = to_wire(s.spectrum);
  w.spreading = to_wire(s.spreading);
  w.depth_m = wire_depth(s.depth_m);
  return w;
}

sim::SceneParams to_sim(const protocol::SceneParams& w) {
  sim::SceneParams s;
  copy_same_fields(w, s);
  s.size_x = w.size_x;
  s.size_z = w.size_z;
  s.spectrum = to_sim(w.spectrum);
  s.spreading = to_sim(w.spreading);
  s.depth_m = sim_depth(w.depth_m);
  return s;
}

}  // namespace ocean::scene_wire
