// Shared reconstruction steps (CODEC.md 7).
#include "frame_reconstruction.hpp"

#include "field_conversion.hpp"
#include "fixed_point.hpp"

namespace ocean::codec {

namespace {

// Per channel in coding order: quarter steps of height and displacement, quarter slope steps of
// the slopes and the displacement's derivatives.
constexpr int kQuantumShift[kCorrectionChannels] = {kHeightQuantumShift, kSlopeQuantumShift, kSlopeQuantumShift,
                                                    kDispQuantumShift,   kDispQuantumShift,  kSlopeQuantumShift,
                                                    kSlopeQuantumShift,  kSlopeQuantumShift};

}  // namespace

void apply_corrections(SampleFields& f, const Corrections& c) {
  std::vector<std::int64_t>* fields[kCorrectionChannels] = {&f.height, &f.slope_x, &f.slope_z,  &f.disp_x,
                                                            &f.disp_z, &f.disp_xx, &f.disp_zz, &f.disp_xz};
  for (int ch = 0; ch < kCorrectionChannels; ++ch) {
    const int shift = kQuantumShift[ch];
    std::vector<std::int64_t>& field = *fields[ch];
    for (const Correction& k : channel(c, ch)) field[k.pos] = wadd(field[k.pos], wshl(k.value, shift));
  }
}

std::vector<std::int64_t> height_correction_field(std::size_t samples, const std::vector<Correction>& height) {
  std::vector<std::int64_t> field(samples, 0);
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

void to_float(const SampleFields& f, const StreamConfig& config, ReconstructedFrame& out, const ParallelFor& parallel) {
  const double hscale = static_cast<double>(config.height_step_m) / 65536.0;
  const double sscale = static_cast<double>(config.slope_step) / 4096.0;
  const double dscale = static_cast<double>(config.disp_step_m) / 65536.0;
  struct Conversion {
    const std::vector<std::int64_t>& from;
    double scale;
    std::vector<float>& to;
  };
  const Conversion conversions[] = {{f.height, hscale, out.height},   {f.slope_x, sscale, out.slope_x},
                                    {f.slope_z, sscale, out.slope_z}, {f.disp_x, dscale, out.disp_x},
                                    {f.disp_z, dscale, out.disp_z},   {f.disp_xx, sscale, out.disp_xx},
                                    {f.disp_zz, sscale, out.disp_zz}, {f.disp_xz, sscale, out.disp_xz}};
  for (const Conversion& c : conversions) c.to.resize(c.from.size());
  out.jacobian.resize(out.disp_xx.size());
  // Sample by sample, so any split of the samples gives the same floats.
  const std::size_t samples = f.height.size();
  const int parts = parallel ? kParallelParts : 1;
  run_jobs(parallel, parts, [&](int part) {
    const std::size_t begin = samples * part / parts, end = samples * (part + 1) / parts;
    for (const Conversion& c : conversions)
      if (!c.from.empty()) scale_fields(c.from.data() + begin, end - begin, c.scale, c.to.data() + begin);
    if (out.jacobian.empty()) return;
    for (std::size_t i = begin; i < end; ++i) {
      // The sim's formula in float: the same operations on (nearly) the same inputs.
      const float xx = out.disp_xx[i], zz = out.disp_zz[i], xz = out.disp_xz[i];
      const float a = 1.0f + xx, b = 1.0f + zz, c = xz * xz;
      const float ab = a * b;
      out.jacobian[i] = ab - c;
    }
  });
}

}  // namespace ocean::codec
