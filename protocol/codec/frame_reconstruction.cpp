// Shared reconstruction steps (CODEC.md 7).
#include "frame_reconstruction.hpp"

#include "fixed_point.hpp"

namespace ocean::codec {

void apply_corrections(SampleFields& f, const Corrections& c) {
  for (const Correction& k : c.height) f.height[k.pos] = wadd(f.height[k.pos], wshl(k.value, kHeightQuantumShift));
  for (const Correction& k : c.slope_x) f.slope_x[k.pos] = wadd(f.slope_x[k.pos], wshl(k.value, kSlopeQuantumShift));
  for (const Correction& k : c.slope_z) f.slope_z[k.pos] = wadd(f.slope_z[k.pos], wshl(k.value, kSlopeQuantumShift));
}

std::vector<std::int64_t> height_correction_field(int n, const std::vector<Correction>& height) {
  std::vector<std::int64_t> field(static_cast<std::size_t>(n) * n, 0);
  for (const Correction& k : height) field[k.pos] = wshl(k.value, kHeightQuantumShift);
  return field;
}

ModalState key_state(const ModalModel& model, std::span<const KeyCoefficient> coefficients, int pos_shift,
                     int vel_shift) {
  ModalState s = model.zero_state();
  const auto& modes = model.key_modes();
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const KeyCoefficient& k = coefficients[i];
    const std::int32_t at = modes[i];
    s.cur.re[at] = wshl(k.xr, pos_shift);
    s.cur.im[at] = wshl(k.xi, pos_shift);
    s.prev.re[at] = wsub(s.cur.re[at], wshl(k.vr, vel_shift));
    s.prev.im[at] = wsub(s.cur.im[at], wshl(k.vi, vel_shift));
  }
  model.mirror_key_column(s.cur);
  model.mirror_key_column(s.prev);
  return s;
}

void to_float(const SampleFields& f, const StreamConfig& config, ReconstructedFrame& out) {
  const double hscale = static_cast<double>(config.height_step_m) / 65536.0;
  const double sscale = static_cast<double>(config.slope_step) / 4096.0;
  out.height.resize(f.height.size());
  for (std::size_t i = 0; i < f.height.size(); ++i)
    out.height[i] = static_cast<float>(static_cast<double>(f.height[i]) * hscale);
  out.slope_x.resize(f.slope_x.size());
  for (std::size_t i = 0; i < f.slope_x.size(); ++i)
    out.slope_x[i] = static_cast<float>(static_cast<double>(f.slope_x[i]) * sscale);
  out.slope_z.resize(f.slope_z.size());
  for (std::size_t i = 0; i < f.slope_z.size(); ++i)
    out.slope_z[i] = static_cast<float>(static_cast<double>(f.slope_z[i]) * sscale);
}

}  // namespace ocean::codec
