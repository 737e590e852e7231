// WakeLattice: where a stream carries the vessels' wake - a square of the world of its own, not the
// sea's repeating patch - and how its waves ring down. The server chooses it (its config's wake
// region), StreamParams carries it (PROTOCOL.md 8) and the codec predicts it (CODEC.md 7.9).
#pragma once

#include <cmath>
#include <cstdint>

namespace ocean {

// grid 0: the stream has none. The wake starts at rest, its modes ring down with damping
// (decay + 2 viscosity k^2), and the server corrects it where the hulls force it.
struct WakeLattice {
  int grid = 0;                 // samples per side, a power of two in [16, 256], or 0
  double size_m = 1024.0;       // the square's side, (0, 1e6] metres
  double origin_x_m = 0.0;      // its corner (x, z minimal) in the world; for rendering only
  double origin_z_m = 0.0;
  double decay_per_s = 0.02;    // amplitude decay rate of every wave, [0, 10] per second
  double viscosity_m2ps = 1e-6; // adds 2 nu k^2 to the decay, [0, 1] m^2/s
  // The wake's bounded history: at tick t it is the response to the hulls during the epoch of
  // t and the one before, epochs of this many ticks from tick 0, each from rest (CODEC.md 7.9).
  std::uint32_t epoch_ticks = 1800;
  bool operator==(const WakeLattice&) const = default;
};

// Of a lattice with grid != 0: nullptr when usable, else which field is wrong and its range.
inline const char* wake_problem(const WakeLattice& w) {
  const auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (w.grid < 16 || w.grid > 256 || (w.grid & (w.grid - 1)) != 0) return "wake grid: a power of two in [16, 256]";
  if (!in(w.size_m, 0.0, 1e6) || w.size_m == 0.0) return "wake size_m: in (0, 1e6] metres";
  if (!in(w.origin_x_m, -1e9, 1e9) || !in(w.origin_z_m, -1e9, 1e9)) return "wake origin: finite, within 1e9 metres";
  if (!in(w.decay_per_s, 0.0, 10.0)) return "wake decay_per_s: in [0, 10] per second";
  if (!in(w.viscosity_m2ps, 0.0, 1.0)) return "wake viscosity_m2ps: in [0, 1] m^2/s";
  if (w.epoch_ticks < 1 || w.epoch_ticks > (1u << 24)) return "wake epoch_ticks: in [1, 2^24]";
  return nullptr;
}

}  // namespace ocean
