// WhitecapCover: how much of the sea is white at a wind speed, and the Jacobian threshold that
// makes the stream's folds cover that much. Observed whitecap cover grows as U^3.41 (Monahan and
// O'Muircheartaigh 1980: about 0.5 % at 8 m/s, 4 % at 15 m/s, 10 % at 20 m/s), while how deep a
// spectral sea folds depends on its grid (a phone's coarser grid folds less) and its choppiness;
// so the threshold is found in the frame the viewer shows: the one at which the foam ramp
// (kFoamBand wide below it) covers the observed share of the tile's samples. Where the sea does
// not fold that much, the foam stops at J = 1 (only compressed water foams). Pure.
#pragma once

#include <span>
#include <vector>

namespace ocean::render {

// The Jacobian range over which foam goes from none to full (FoamMemory's rate is set against it).
inline constexpr float kFoamBand = 0.2f;

struct WhitecapShading {
  float threshold = 1.0f;  // foam where the Jacobian is below this, full kFoamBand lower
  float cover = 0.0f;      // the mean foam of the samples at that threshold: the far field's foam
};

class WhitecapCover {
 public:
  // The observed share of the sea surface covered by whitecaps at a 10 m wind speed (fraction).
  static double observed(double wind_mps);

  void set_wind_mps(double wind_mps) { wind_mps_ = wind_mps; }
  // The shading for this frame's Jacobian (the tile's samples): the threshold follows the frame's
  // own over about half a second (wave groups come and go; the foam does not flicker with them).
  WhitecapShading update(std::span<const float> jacobian, double dt_s);
  void clear() { primed_ = false; }

 private:
  // The mean foam of the sorted samples at threshold t.
  double mean_foam(double t) const;

  double wind_mps_ = 0.0;
  std::vector<float> sorted_;
  std::vector<double> prefix_;  // prefix_[k] = sum of the k smallest samples
  float threshold_ = 1.0f;
  bool primed_ = false;
};

}  // namespace ocean::render
