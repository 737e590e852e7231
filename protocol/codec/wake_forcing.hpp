// WakeForcing: the hulls' pressure on the wake lattice at every tick (CODEC.md 7.9), from the
// vessels' tracks: each hull at its pose half a tick after the tick (the middle of the step that
// starts there), as Fourier coefficients in the stream's height units (model/hull_pressure.hpp in
// the Det arithmetic), so every decoder and the encoder predict the same forcing. Kept per tick,
// since every delta that advances across a tick needs it.
#pragma once

#include "hull_pressure.hpp"
#include "stream_config.hpp"
#include "tick.hpp"
#include "vessel_track.hpp"

#include <complex>
#include <map>
#include <vector>

namespace ocean::codec {

class WakeForcing {
 public:
  // `config` must have a wake lattice.
  WakeForcing(const StreamConfig& config, std::vector<model::VesselTrack> vessels);
  // The fleet `vessels` from tick `from` on, succeeding `earlier`'s (a vessel command): the two
  // press alike before `from` (a command ends and starts presences there), so the history
  // `earlier` advanced up to `from` and its pressures before it are kept, not recomputed.
  WakeForcing(const WakeForcing& earlier, std::vector<model::VesselTrack> vessels, Tick from);

  // The pressure of every hull during the step from tick t to t + 1, per wake mode.
  const std::vector<std::complex<double>>& pressure(Tick t);

  const std::vector<model::VesselTrack>& vessels() const { return vessels_; }
  std::int64_t epoch_ticks() const { return epoch_ticks_; }

  // The wake one epoch's forcing leaves (CODEC.md 7.9): the wake lattice's modes from rest at the
  // epoch's first tick, forced during the epoch only, at tick `at` (X(at - 1), X(at)). Kept here
  // for the SceneTimeline that advances them; the last few epochs.
  struct Part {
    std::int64_t epoch = 0;
    Tick at = 0;
    std::vector<std::int64_t> prev_re, prev_im, cur_re, cur_im;
  };
  Part& part(std::int64_t epoch);

 private:
  std::int64_t epoch_ticks_;
  std::map<std::int64_t, Part> parts_;
  StreamConfig::Lattice lattice_;
  double origin_x_m_, origin_z_m_, rate_hz_, scale_;
  std::vector<model::VesselTrack> vessels_;
  model::HullPressure<model::Det> hulls_;
  std::vector<model::HullPose> poses_;  // this tick's, reused
  std::map<Tick, std::vector<std::complex<double>>> ticks_;  // the newest ones asked for
};

}  // namespace ocean::codec
