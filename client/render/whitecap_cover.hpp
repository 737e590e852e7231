// WhitecapCover: how much of the sea is white at a wind speed, and the Jacobian threshold that
// makes the stream's folds bring the foam to that much. Observed whitecap cover grows as U^3.41
// (Monahan and O'Muircheartaigh 1980: about 0.5 % at 8 m/s, 4 % at 15 m/s, 10 % at 20 m/s), while
// how deep a spectral sea folds depends on its grid (a phone's coarser grid folds less) and its
// choppiness; so the threshold is found in the frame the viewer shows: the one at which the
// foam - a ramp below it, or what earlier folds left (FoamField) where that is more - covers the
// observed share of the tile. Foam is a cover: a sample at 0.5 is half white (the shader draws it
// as lace of that density), so the share is the mean foam. The ramp is half as wide as the
// frame's deepest folds go below 1 (at most kFoamBand): a shallow sea's broad gentle compressions
// would otherwise take the share as a faint haze instead of its crests. Where the sea does not
// fold that much, the foam stops at J = 1 (only compressed water foams). Pure.
#pragma once

#include <span>
#include <vector>

namespace ocean::render {

// The widest Jacobian range over which foam goes from none to full.
inline constexpr float kFoamBand = 0.2f;

struct WhitecapShading {
  float threshold = 1.0f;  // foam where the Jacobian is below this, full `band` lower
  float band = kFoamBand;
  float cover = 0.0f;      // the mean foam drawn on the tile: the far field's foam
  float wind_x = 1.0f, wind_z = 0.0f;  // unit, where the wind blows: the foam's streaks lie along it
};

class WhitecapCover {
 public:
  // The observed share of the sea surface covered by whitecaps at a 10 m wind speed (fraction).
  static double observed(double wind_mps);

  void set_wind_mps(double wind_mps) { wind_mps_ = wind_mps; }
  // The threshold for this frame's Jacobian (the tile's samples) over `past` (the foam already
  // there, same layout, or empty): it follows the frame's own over about half a second (wave
  // groups come and go; the foam does not flicker with them).
  WhitecapShading update(std::span<const float> jacobian, std::span<const float> past, double dt_s);
  void clear() { primed_ = false; }

 private:
  // The mean foam of the samples at threshold t: max(the fold's ramp, what is already there).
  double mean_foam(double t) const;

  double wind_mps_ = 0.0;
  std::vector<float> j_, past_;  // a strided subset of the tile's samples
  std::vector<float> low_;       // scratch: j_ partly ordered
  float threshold_ = 1.0f;
  float band_ = kFoamBand;
  bool primed_ = false;
};

}  // namespace ocean::render
