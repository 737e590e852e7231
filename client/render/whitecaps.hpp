// Whitecaps: the foam a viewer draws from a choppy stream - its cover driven to the one observed
// at the wind (WhitecapCover), its life on the tile (FoamField) - handed to the renderer in the
// tile's Jacobian stream (Renderer::set_whitecaps). Pure.
#pragma once

#include <span>
#include <vector>

#include "client/render/foam_field.hpp"
#include "client/render/whitecap_cover.hpp"

namespace ocean::render {

class Whitecaps {
 public:
  void set_wind(const FoamWind& wind) {
    wind_ = wind;
    cover_.set_wind_mps(wind.speed_mps);
  }
  // jacobian: the frame's Jacobian over all its lattices, the tile's n x n (over patch_x_m x
  // patch_z_m) first. Returns the stream to upload, same layout: the tile's foam (0..1), then the
  // other lattices' Jacobians.
  std::span<const float> shade(std::span<const float> jacobian, int n, float patch_x_m, float patch_z_m, double dt_s);
  // The last shade()'s threshold, and the mean foam of its tile (the far field's foam).
  const WhitecapShading& shading() const { return shading_; }
  const WhitecapCover& cover() const { return cover_; }
  void clear() {
    cover_.clear();
    field_.clear();
  }

 private:
  WhitecapCover cover_;
  FoamField field_;
  FoamWind wind_;
  std::vector<float> ramp_, shaded_;
  WhitecapShading shading_;
};

}  // namespace ocean::render
