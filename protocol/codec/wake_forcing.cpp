#include "wake_forcing.hpp"

#include <stdexcept>

namespace ocean::codec {
namespace {

constexpr std::size_t kKeptTicks = 256;

}  // namespace

WakeForcing::WakeForcing(const StreamConfig& config, std::vector<model::VesselTrack> vessels)
    : lattice_(config.lattices().back()),
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

const std::vector<std::complex<double>>& WakeForcing::pressure(Tick t) {
  if (auto it = ticks_.find(t); it != ticks_.end()) return it->second;
  if (ticks_.size() >= kKeptTicks) ticks_.erase(ticks_.begin());
  std::vector<std::complex<double>>& p = ticks_[t];
  p.assign(static_cast<std::size_t>(lattice_.n) * (lattice_.n / 2 + 1), {});
  // Ticks as signed: the step before tick 0 is at -0.5 ticks, before every track's start.
  const double time_s = (static_cast<double>(static_cast<std::int64_t>(t)) + 0.5) / rate_hz_;
  for (const model::VesselTrack& v : vessels_) {
    model::HullPose pose = model::pose_at(v, time_s);
    pose.x_m -= origin_x_m_;
    pose.z_m -= origin_z_m_;
    hulls_.add(pose, scale_, p.data());
  }
  return p;
}

}  // namespace ocean::codec
