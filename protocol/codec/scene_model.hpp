// SceneModel: the ocean's state at any tick predicted from the scene parameters and the seed alone,
// bit-identically on every platform, so that a key frame costs only corrections and a weather
// change costs nothing. It evaluates the sea model (model/) in the Det arithmetic: the sim's libm
// results differ between platforms in the last bits, which would break the closed loop. CODEC.md
// 7.6 is the normative description.
#pragma once

#include "modal_model.hpp"
#include "scene_params.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <vector>

namespace ocean::codec {

// Sim time of a tick at `rate_hz` ticks per second, as the server's TickClock::sim_time_s computes
// it: whole seconds (floor division) plus the fraction, so large tick counts keep full precision.
double tick_time_s(std::int64_t tick, int rate_hz);

class SceneModel {
 public:
  // Per-mode tables of the stream's half spectrum (h0(k), conj h0(-k), w) built once, for each of
  // its lattices from that cascade's scene (CODEC.md 7.7). Throws
  // std::invalid_argument when the stream grid exceeds size_x/size_z, the stream's patch, gravity
  // or depth differ from the scene's, or the values are unusable (invalid, or a mode too large
  // for int64 units).
  SceneModel(const StreamConfig& stream, const model::SceneParams& scene);

  // The decoder state the scene predicts: out.cur = X(tick), out.prev = X(tick - 1) (tick 0: prev =
  // X(-1), time may be negative), X = the unnormalized DFT of the stream's band-limited height field
  // in units u = height_step_m / 2^16, i.e. X(r, c) = n^2 h(k, t) / u rounded with to_fixed(., 0),
  // Hermitian-exact like ModalModel's key state (DC, Nyquist row/column 0; column 0 rows
  // n/2+1..n-1 the conjugates of rows n-r).
  void state_at(std::uint64_t tick, ModalState& out) const;

  const model::SceneParams& scene() const { return scene_; }

 private:
  // One nonzero mode: h(t) n^2 / u = (sum_re cos p + diff_im sin p) + i (sum_im cos p - diff_re sin p)
  // with p = w t, sum = (a + b) n^2 / u, diff = (a - b) n^2 / u, a = h0(k), b = conj h0(-k).
  struct Mode {
    std::int32_t index;  // into the half spectrum, r * (n/2 + 1) + c
    double omega;
    double sum_re, sum_im, diff_re, diff_im;
  };

  struct LatticeAt {
    int n;
    std::size_t modes_at;
  };
  void add_lattice(const StreamConfig::Lattice& lattice, const model::SceneParams& scene, double unit);

  model::SceneParams scene_;
  int rate_hz_;
  std::vector<Mode> modes_;  // every lattice's, their indices into the stream's half spectrum
  std::vector<LatticeAt> lattices_;
  std::size_t total_modes_ = 0;
};

}  // namespace ocean::codec
