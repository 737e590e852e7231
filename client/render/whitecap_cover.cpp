#include "client/render/whitecap_cover.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {

namespace {

constexpr std::size_t kMaxSamples = 8192;  // a strided subset of larger grids: the share, not the places
constexpr double kFollowS = 0.5;
constexpr float kMaxThreshold = 1.0f;
constexpr double kMaxCover = 0.5;          // beyond hurricane force the formula leaves the data

}  // namespace

double WhitecapCover::observed(double wind_mps) {
  if (!(wind_mps > 0.0)) return 0.0;
  return std::min(kMaxCover, 3.84e-6 * std::pow(wind_mps, 3.41));
}

double WhitecapCover::mean_foam(double t) const {
  const auto n = static_cast<double>(sorted_.size());
  const auto below = [&](double x) {
    return static_cast<std::size_t>(std::lower_bound(sorted_.begin(), sorted_.end(), static_cast<float>(x)) - sorted_.begin());
  };
  const std::size_t full = below(t - kFoamBand), some = below(t);
  const double ramp = (static_cast<double>(some - full) * t - (prefix_[some] - prefix_[full])) / kFoamBand;
  return (static_cast<double>(full) + ramp) / n;
}

WhitecapShading WhitecapCover::update(std::span<const float> jacobian, double dt_s) {
  const double target = observed(wind_mps_);
  if (jacobian.empty() || target <= 0.0) {
    primed_ = false;
    return {kMaxThreshold, 0.0f};
  }
  const std::size_t stride = (jacobian.size() + kMaxSamples - 1) / kMaxSamples;
  sorted_.clear();
  for (std::size_t i = 0; i < jacobian.size(); i += stride) sorted_.push_back(jacobian[i]);
  std::sort(sorted_.begin(), sorted_.end());
  prefix_.assign(sorted_.size() + 1, 0.0);
  for (std::size_t i = 0; i < sorted_.size(); ++i) prefix_[i + 1] = prefix_[i] + sorted_[i];
  // mean_foam grows with t: bisect for the threshold that covers the target share.
  double lo = static_cast<double>(sorted_.front()), hi = kMaxThreshold;
  if (mean_foam(hi) > target)
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (mean_foam(mid) < target ? lo : hi) = mid;
    }
  const auto wanted = static_cast<float>(hi);
  const double follow = primed_ ? std::clamp(dt_s / kFollowS, 0.0, 1.0) : 1.0;
  threshold_ += static_cast<float>(follow) * (wanted - threshold_);
  primed_ = true;
  return {threshold_, static_cast<float>(mean_foam(threshold_))};
}

}  // namespace ocean::render
