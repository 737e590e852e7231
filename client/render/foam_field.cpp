#include "client/render/foam_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocean::render {

namespace {

constexpr double kDriftPerWind = 0.03;    // surface drift over the 10 m wind
// Along-wind spreading of the remnant, m^2/s per m/s of wind: at 20 m/s a patch is drawn out by
// about 6 m in its first 3 s (sqrt(2 D t)); across the wind it keeps its width.
constexpr double kStreakPerWind = 0.3;

}  // namespace

float FoamField::sample(float col, float row) const {
  const int n = n_;
  const float fc = std::floor(col), fr = std::floor(row);
  const float tc = col - fc, tr = row - fr;
  const auto wrap = [n](float v) { return static_cast<int>(((static_cast<long>(v) % n) + n) % n); };
  const int c0 = wrap(fc), r0 = wrap(fr), c1 = (c0 + 1) % n, r1 = (r0 + 1) % n;
  const auto at = [&](int r, int c) { return remnant_[static_cast<std::size_t>(r) * n + c]; };
  const float lo = at(r0, c0) + tc * (at(r0, c1) - at(r0, c0));
  const float hi = at(r1, c0) + tc * (at(r1, c1) - at(r1, c0));
  return lo + tr * (hi - lo);
}

void FoamField::carry(float drift_x, float drift_z, float h_x, float h_z) {
  const int n = n_;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const float col = static_cast<float>(c) - drift_x, row = static_cast<float>(r) - drift_z;
      carried_[static_cast<std::size_t>(r) * n + c] =
          0.5f * sample(col, row) + 0.25f * (sample(col + h_x, row + h_z) + sample(col - h_x, row - h_z));
    }
}

std::span<const float> FoamField::advance(int n, float patch_x_m, float patch_z_m, const FoamWind& wind, double dt_s) {
  const std::size_t count = static_cast<std::size_t>(std::max(n, 0)) * std::max(n, 0);
  if (count == 0 || !(patch_x_m > 0.0f) || !(patch_z_m > 0.0f)) {
    n_ = 0;
    past_.clear();
    return past_;
  }
  if (n != n_) {
    n_ = n;
    breaking_.assign(count, 0.0f);
    remnant_.assign(count, 0.0f);
    carried_.assign(count, 0.0f);
    past_.assign(count, 0.0f);
    return past_;
  }
  const double dt = std::clamp(dt_s, 0.0, 1.0);
  const double angle = wind.dir_deg * std::numbers::pi / 180.0;
  const double ux = std::cos(angle), uz = std::sin(angle);
  const double speed = std::max(0.0, wind.speed_mps);
  const double drift = kDriftPerWind * speed * dt;
  const double h = std::sqrt(4.0 * kStreakPerWind * speed * dt);  // a [1/4 1/2 1/4] blur adds h^2 / 2 of variance
  const double cell_x = patch_x_m / n, cell_z = patch_z_m / n;
  carry(static_cast<float>(drift * ux / cell_x), static_cast<float>(drift * uz / cell_z), static_cast<float>(h * ux / cell_x),
        static_cast<float>(h * uz / cell_z));
  const auto breaking_decay = static_cast<float>(std::exp(-dt / kBreakingS));
  const auto remnant_decay = static_cast<float>(std::exp(-dt / kRemnantS));
  for (std::size_t i = 0; i < count; ++i) {
    breaking_[i] *= breaking_decay;
    remnant_[i] = carried_[i] * remnant_decay;
    past_[i] = std::max(breaking_[i], remnant_[i]);
  }
  return past_;
}

const std::vector<float>& FoamField::add(std::span<const float> whitecap) {
  const std::size_t count = past_.size();
  if (whitecap.size() != count) {
    out_.assign(whitecap.begin(), whitecap.end());
    mean_ = 0.0;
    return out_;
  }
  out_.resize(count);
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    breaking_[i] = std::max(std::clamp(whitecap[i], 0.0f, 1.0f), breaking_[i]);
    remnant_[i] = std::max(remnant_[i], kRemnantLevel * breaking_[i]);
    out_[i] = std::max(breaking_[i], remnant_[i]);
    sum += out_[i];
  }
  mean_ = count ? sum / static_cast<double>(count) : 0.0;
  return out_;
}

}  // namespace ocean::render
