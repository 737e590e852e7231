#include "wake_forcing.hpp"

#include <stdexcept>

namespace ocean::codec {
namespace {

constexpr std::size_t kKeptTicks = 256;

}  // namespace

WakeForcing::WakeForcing(const StreamConfig& config, std::vector<model::VesselTrack> vessels)
    : epoch_ticks_(config.wake.epoch_ticks),
      lattice_(config.lattices().back()),
      origin_x_m_(config.wake.origin_x_m),
      origin_z_m_(config.wake.origin_z_m),
      rate_hz_(static_cast<double>(config.effective_tick_rate_hz())),
      // Fourier coefficients in metres to the codec's half spectrum: the unnormalized DFT of a
      // field in height units (CODEC.md 2).
      scale_(static_cast<double>(lattice_.n) * static_cast<double>(lattice_.n) /
             (static_cast<double>(config.height_step_m) / 65536.0)),
      vessels_(std::move(vessels)),
      hulls_(lattice_.n, lattice_.patch_x_m) {
  if (!lattice_.wake) throw std::invalid_argument("WakeForcing: the stream has no wake lattice");
}

WakeForcing::WakeForcing(const WakeForcing& earlier, std::vector<model::VesselTrack> vessels, Tick from)
    : epoch_ticks_(earlier.epoch_ticks_),
      lattice_(earlier.lattice_),
      origin_x_m_(earlier.origin_x_m_),
      origin_z_m_(earlier.origin_z_m_),
      rate_hz_(earlier.rate_hz_),
      scale_(earlier.scale_),
      vessels_(std::move(vessels)),
      hulls_(lattice_.n, lattice_.patch_x_m) {
  // A part at tick `at` used the pressures of ticks before it; one past `from` starts again.
  for (const auto& [epoch, p] : earlier.parts_)
    if (p.at <= from) parts_.emplace(epoch, p);
  for (const auto& [t, p] : earlier.ticks_)
    if (t < from) ticks_.emplace(t, p);
}

WakeForcing::Part& WakeForcing::part(std::int64_t epoch) {
  auto it = parts_.find(epoch);
  if (it != parts_.end()) return it->second;
  while (parts_.size() >= 4) parts_.erase(parts_.begin());  // an epoch is needed for two epochs
  Part& p = parts_[epoch];
  p.epoch = epoch;
  p.at = static_cast<Tick>(epoch * epoch_ticks_);
  const std::size_t modes = static_cast<std::size_t>(lattice_.n) * (lattice_.n / 2 + 1);
  for (auto* v : {&p.prev_re, &p.prev_im, &p.cur_re, &p.cur_im}) v->assign(modes, 0);
  return p;
}

const std::vector<std::complex<double>>& WakeForcing::pressure(Tick t) {
  if (auto it = ticks_.find(t); it != ticks_.end()) return it->second;
  if (ticks_.size() >= kKeptTicks) ticks_.erase(ticks_.begin());
  std::vector<std::complex<double>>& p = ticks_[t];
  p.assign(static_cast<std::size_t>(lattice_.n) * (lattice_.n / 2 + 1), {});
  // Ticks as signed: the step before tick 0 is at -0.5 ticks, before every track's start.
  const double time_s = (static_cast<double>(static_cast<std::int64_t>(t)) + 0.5) / rate_hz_;
  poses_.clear();
  for (const model::VesselTrack& v : vessels_) {
    if (!model::present_at(v.presence, time_s)) continue;  // a dropped object between splashes
    model::HullPose pose = model::pose_at(v, time_s);
    pose.x_m -= origin_x_m_;
    pose.z_m -= origin_z_m_;
    poses_.push_back(pose);
  }
  hulls_.add(poses_, scale_, p.data());
  return p;
}

}  // namespace ocean::codec
