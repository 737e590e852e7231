#include "client/render/whitecap_cover.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {

namespace {

constexpr std::size_t kMaxSamples = 8192;  // a strided subset of larger grids: the share, not the places
constexpr double kFollowS = 0.5;
constexpr float kMaxThreshold = 1.0f;
constexpr double kMaxCover = 0.5;          // beyond hurricane force the formula leaves the data
constexpr float kMinBand = 0.04f;

}  // namespace

double WhitecapCover::observed(double wind_mps) {
  if (!(wind_mps > 0.0)) return 0.0;
  return std::min(kMaxCover, 3.84e-6 * std::pow(wind_mps, 3.41));
}

double WhitecapCover::mean_foam(double t) const {
  double sum = 0.0;
  const auto tf = static_cast<float>(t);
  for (std::size_t i = 0; i < j_.size(); ++i) sum += std::max(std::clamp((tf - j_[i]) / band_, 0.0f, 1.0f), past_[i]);
  return sum / static_cast<double>(j_.size());
}

WhitecapShading WhitecapCover::update(std::span<const float> jacobian, std::span<const float> past, double dt_s) {
  const double target = observed(wind_mps_);
  if (jacobian.empty() || target <= 0.0) {
    primed_ = false;
    return {kMaxThreshold, 0.0f};
  }
  const bool has_past = past.size() == jacobian.size();
  const std::size_t stride = (jacobian.size() + kMaxSamples - 1) / kMaxSamples;
  j_.clear();
  past_.clear();
  for (std::size_t i = 0; i < jacobian.size(); i += stride) {
    j_.push_back(jacobian[i]);
    past_.push_back(has_past ? past[i] : 0.0f);
  }
  low_.assign(j_.begin(), j_.end());  // the deepest folds: the thousandth of the samples lowest
  const auto deep = low_.begin() + static_cast<std::ptrdiff_t>(low_.size() / 1000);
  std::nth_element(low_.begin(), deep, low_.end());
  band_ = std::clamp(0.5f * (1.0f - *deep), kMinBand, kFoamBand);
  // mean_foam grows with t: bisect for the threshold that brings the foam to the target share;
  // the lowest Jacobian (no new foam) when what is there already covers it.
  double lo = static_cast<double>(*std::min_element(j_.begin(), j_.end())), hi = kMaxThreshold;
  if (mean_foam(lo) >= target)
    hi = lo;
  else if (mean_foam(hi) > target)
    for (int i = 0; i < 16; ++i) {  // to 1e-5 of J
      const double mid = 0.5 * (lo + hi);
      (mean_foam(mid) < target ? lo : hi) = mid;
    }
  const auto wanted = static_cast<float>(hi);
  const double follow = primed_ ? std::clamp(dt_s / kFollowS, 0.0, 1.0) : 1.0;
  threshold_ += static_cast<float>(follow) * (wanted - threshold_);
  // A frame that cannot reach the share (a stream's first, before its folds; a sea that barely
  // folds) is not followed from: the next that can starts afresh instead of foaming every
  // compression while the threshold comes down.
  primed_ = wanted < kMaxThreshold;
  WhitecapShading out;
  out.threshold = threshold_;
  out.band = band_;
  out.cover = static_cast<float>(mean_foam(threshold_));
  return out;
}

}  // namespace ocean::render
