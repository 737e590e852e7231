// The scene's mode table (h0 pairs scaled to spectrum units, w as ModalModel computes it) and its
// per-tick evaluation h(k, t) = a e^{-iwt} + b e^{+iwt}, as the sim's band evaluator does it.
#include "scene_model.hpp"

#include "arithmetic.hpp"
#include "cascade_scene.hpp"
#include "dispersion.hpp"
#include "fft_bin.hpp"
#include "initial_amplitude.hpp"
#include "spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace ocean::codec {
namespace {

const model::SceneParams& require_valid(const StreamConfig& stream, const model::SceneParams& scene) {
  std::string err = validate(stream);
  if (!err.empty()) throw std::invalid_argument("scene model: stream config: " + err);
  err = validate(scene);
  if (!err.empty()) throw std::invalid_argument("scene model: scene: " + err);
  if (stream.cascades.empty() && (stream.grid > scene.size_x || stream.grid > scene.size_z))
    throw std::invalid_argument("scene model: stream grid " + std::to_string(stream.grid) +
                                " exceeds the scene's size " + std::to_string(scene.size_x) + " x " +
                                std::to_string(scene.size_z));
  // The recurrence the decoder advances with is built from the stream's physics; a scene with other
  // physics would predict a different ocean from the one the stream advances.
  if (stream.patch_x_m != scene.patch_x_m || stream.patch_z_m != scene.patch_z_m ||
      stream.gravity_mps2 != scene.gravity_mps2 || stream.depth_m != model::wire_depth(scene.depth_m))
    throw std::invalid_argument("scene model: the stream's patch, gravity and depth must equal the scene's");
  return scene;
}

// Each component of a mode must stay well inside int64 after to_fixed.
constexpr double kMaxUnits = 0x1.0p62;

}  // namespace

double tick_time_s(std::int64_t tick, int rate_hz) {
  std::int64_t seconds = tick / rate_hz;
  if (tick % rate_hz < 0) --seconds;  // floor division
  return static_cast<double>(seconds) + static_cast<double>(tick - seconds * rate_hz) / rate_hz;
}

SceneModel::SceneModel(const StreamConfig& stream, const model::SceneParams& scene)
    : scene_(require_valid(stream, scene)), rate_hz_(stream.effective_tick_rate_hz()) {
  const double unit = static_cast<double>(stream.height_step_m) / 65536.0;
  const std::vector<StreamConfig::Lattice> lattices = stream.lattices();
  for (std::size_t i = 0; i < lattices.size(); ++i) {
    const StreamConfig::Lattice& l = lattices[i];
    if (l.wake) continue;  // the wake starts at rest: no scene draws it (CODEC.md 7.9)
    // A cascade's waves are its own scene's (CODEC.md 7.7); one lattice is the scene itself.
    const model::SceneParams own =
        stream.cascades.empty() ? scene_ : model::cascade_scene(scene_, stream.cascades[i], static_cast<int>(i));
    add_lattice(l, own, unit);
  }
  total_modes_ = stream.modes();
}

void SceneModel::add_lattice(const StreamConfig::Lattice& l, const model::SceneParams& scene, double unit) {
  const model::Spectrum<model::Det> spectrum(scene);
  const int n = l.n, hc = n / 2 + 1;
  const double scale = static_cast<double>(n) * static_cast<double>(n) / unit;
  lattices_.push_back({n, l.modes_at});
  for (int r = 0; r < n; ++r) {
    const int kz = signed_index(r, n);
    if (r == n / 2) continue;  // Nyquist row
    const double wz = model::kTwoPi * kz / l.patch_z_m;
    for (int c = 0; c < n / 2; ++c) {  // column n/2 is the Nyquist column
      if (c == 0 && kz <= 0) continue;  // DC, and the kx = 0 partners mirrored in state_at
      const double wx = model::kTwoPi * c / l.patch_x_m;
      const std::complex<double> a = model::initial_amplitude(scene, spectrum, c, kz);
      const std::complex<double> b = std::conj(model::initial_amplitude(scene, spectrum, -c, -kz));
      Mode m;
      m.index = static_cast<std::int32_t>(l.modes_at) + r * hc + c;
      m.omega = model::angular_frequency<model::Det>(model::Det::hypot(wx, wz), scene.gravity_mps2, scene.depth_m);
      m.sum_re = (a.real() + b.real()) * scale;
      m.sum_im = (a.imag() + b.imag()) * scale;
      m.diff_re = (a.real() - b.real()) * scale;
      m.diff_im = (a.imag() - b.imag()) * scale;
      if (m.sum_re == 0.0 && m.sum_im == 0.0 && m.diff_re == 0.0 && m.diff_im == 0.0) continue;
      if (!(std::fabs(m.sum_re) + std::fabs(m.diff_im) < kMaxUnits &&
            std::fabs(m.sum_im) + std::fabs(m.diff_re) < kMaxUnits))
        throw std::invalid_argument("scene model: the wave (" + std::to_string(c) + ", " + std::to_string(kz) +
                                    ") is too large for the stream's height step (beyond 2^62 units)");
      modes_.push_back(m);
    }
  }
}

void SceneModel::state_at(std::uint64_t tick, ModalState& out) const {
  const std::size_t size = total_modes_;
  for (HalfSpectrum* s : {&out.cur, &out.prev}) {
    s->re.assign(size, 0);
    s->im.assign(size, 0);
  }
  const std::int64_t signed_tick = static_cast<std::int64_t>(tick);
  const double t_cur = tick_time_s(signed_tick, rate_hz_);
  const double t_prev = tick_time_s(signed_tick - 1, rate_hz_);

  // Phases of a block of modes at both times go through the batched det_cos_sin together.
  constexpr std::size_t kBlock = 64;
  double phase[2 * kBlock], cos_p[2 * kBlock], sin_p[2 * kBlock];
  for (std::size_t at = 0; at < modes_.size(); at += kBlock) {
    const std::size_t count = std::min(kBlock, modes_.size() - at);
    for (std::size_t i = 0; i < count; ++i) {
      phase[i] = modes_[at + i].omega * t_cur;
      phase[kBlock + i] = modes_[at + i].omega * t_prev;
    }
    model::det_cos_sin(phase, count, cos_p, sin_p);
    model::det_cos_sin(phase + kBlock, count, cos_p + kBlock, sin_p + kBlock);
    for (std::size_t i = 0; i < count; ++i) {
      const Mode& m = modes_[at + i];
      for (int which = 0; which < 2; ++which) {
        HalfSpectrum& s = which == 0 ? out.cur : out.prev;
        const double c = cos_p[which * kBlock + i], sn = sin_p[which * kBlock + i];
        s.re[m.index] = model::to_fixed(m.sum_re * c + m.diff_im * sn, 0);
        s.im[m.index] = model::to_fixed(m.sum_im * c - m.diff_re * sn, 0);
      }
    }
  }
  // Column kx = 0 holds k and -k: rows n/2+1..n-1 are exactly the conjugates of rows n - r.
  for (const LatticeAt& l : lattices_) {
    const std::size_t n = static_cast<std::size_t>(l.n), hc = n / 2 + 1;
    for (HalfSpectrum* s : {&out.cur, &out.prev})
      for (std::size_t r = n / 2 + 1; r < n; ++r) {
        s->re[l.modes_at + r * hc] = s->re[l.modes_at + (n - r) * hc];
        s->im[l.modes_at + r * hc] = -s->im[l.modes_at + (n - r) * hc];
      }
  }
}

}  // namespace ocean::codec
