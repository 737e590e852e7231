// FieldExtent: how large a scene's fields are expected to be on one lattice, from its spectrum
// alone (no draw): the root-mean-square of the heights, slopes, choppy displacement and its
// derivatives summed over the lattice's modes. A stream quantizes each field to a fixed number of
// steps (the codec carries at most 2^20 each way), so a scene whose waves would not fit is refused
// before it is simulated, with these figures in the reason (server/net/config/servable_scene.hpp).
#pragma once

#include "sea_model.hpp"

namespace ocean::sim {

struct FieldExtent {
  double height_m = 0.0;      // RMS of h
  double slope = 0.0;         // RMS of the steeper of dh/dx, dh/dz
  double displacement_m = 0.0;  // RMS of the larger choppy displacement, choppiness included
  double displacement_slope = 0.0;  // RMS of the largest of its derivatives xx, zz, xz
};

// Over the size_x x size_z modes of `lattice` its band keeps (the modes a frame of it sums), with
// the expected |h0|^2 of each (initial_amplitude.hpp: E|h0|^2 = P(k) dkx dkz / 2 at k and -k).
// `lattice` must be valid.
FieldExtent expected_extent(const SceneParams& lattice);

}  // namespace ocean::sim
