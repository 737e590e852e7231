// FoamField: foam that lives. A whitecap flares where a crest folds and stays bright while it
// breaks, about a second; it leaves a thinner patch that drifts with the wind's surface drift
// (about 3 % of the wind), is drawn out along the wind into streaks, and fades over several
// seconds (Monahan's stage A and stage B whitecaps). Kept on the tile's periodic grid and advanced
// every frame from the frame's own folds and the scene's wind: no wire data. Pure.
#pragma once

#include <span>
#include <vector>

namespace ocean::render {

struct FoamWind {
  double speed_mps = 0.0;
  double dir_deg = 0.0;  // the direction it blows towards, from +x towards +z (the scene's)
};

class FoamField {
 public:
  // Seconds a breaking crest's foam takes to fall to 1/e once it stops folding, the level its
  // remnant starts at, and the remnant's own 1/e time.
  static constexpr double kBreakingS = 0.4;
  static constexpr float kRemnantLevel = 0.4f;
  static constexpr double kRemnantS = 2.5;

  // A frame in two steps. advance: the foam the past leaves on an n x n grid (rows along +z)
  // over a patch_x_m x patch_z_m periodic tile, dt later - breaking foam fading, remnants carried
  // by the wind and fading (a new grid starts over; dt is clamped to [0, 1] s so a stall does not
  // jump). add: this frame's foam from folds (0..1, same layout); returns the foam to shade,
  // the larger of the two at each sample.
  std::span<const float> advance(int n, float patch_x_m, float patch_z_m, const FoamWind& wind, double dt_s);
  const std::vector<float>& add(std::span<const float> whitecap);
  // The mean of the last frame's foam: the share of the sea it whitens.
  double mean() const { return mean_; }
  void clear() { n_ = 0; }

 private:
  // The remnant moved on by the drift and drawn out along the wind (three taps h cells apart).
  void carry(float drift_x, float drift_z, float h_x, float h_z);
  float sample(float col, float row) const;  // bilinear, periodic, in grid units

  int n_ = 0;
  std::vector<float> breaking_, remnant_, carried_, past_, out_;
  double mean_ = 0.0;
};

}  // namespace ocean::render
