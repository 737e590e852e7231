// Shared reconstruction steps (CODEC.md 7).
#include "frame_reconstruction.hpp"

#include "field_conversion.hpp"
#include "fixed_point.hpp"

#include <algorithm>
#include <array>

namespace ocean::codec {

namespace {

// Per channel in coding order: what one unit of its field is in the output's units.
std::array<double, kCorrectionChannels> output_scales(const StreamConfig& config) {
  std::array<double, kCorrectionChannels> scales;
  for (int ch = 0; ch < kCorrectionChannels; ++ch) scales[ch] = unit_scale(config, kChannels[ch].unit);
  return scales;
}

int channel_shift(int ch) { return quantum_shift(kChannels[ch].unit); }

std::array<std::vector<float>*, kCorrectionChannels> outputs(ReconstructedFrame& out) {
  std::array<std::vector<float>*, kCorrectionChannels> to;
  for (int ch = 0; ch < kCorrectionChannels; ++ch) to[ch] = &(out.*kReconstructedChannels[ch]);
  return to;
}

void jacobian(ReconstructedFrame& out, std::size_t begin, std::size_t end) {
  if (out.jacobian.empty()) return;
  for (std::size_t i = begin; i < end; ++i) {
    // The sim's formula in float: the same operations on (nearly) the same inputs.
    const float xx = out.disp_xx[i], zz = out.disp_zz[i], xz = out.disp_xz[i];
    const float a = 1.0f + xx, b = 1.0f + zz, c = xz * xz;
    const float ab = a * b;
    out.jacobian[i] = ab - c;
  }
}

// A channel's corrections summed per sample (wrapping adds commute, so the order they came in
// does not matter), by position.
struct CorrectionSum {
  std::uint32_t pos;
  std::int64_t add;
};

std::vector<CorrectionSum> summed(const std::vector<Correction>& corrections, int shift) {
  std::vector<CorrectionSum> sums;
  sums.reserve(corrections.size());
  for (const Correction& k : corrections) sums.push_back({k.pos, wshl(k.value, shift)});
  std::sort(sums.begin(), sums.end(), [](const CorrectionSum& a, const CorrectionSum& b) { return a.pos < b.pos; });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (kept > 0 && sums[kept - 1].pos == sums[i].pos) sums[kept - 1].add = wadd(sums[kept - 1].add, sums[i].add);
    else sums[kept++] = sums[i];
  }
  sums.resize(kept);
  return sums;
}

}  // namespace

void apply_corrections(SampleFields& f, const Corrections& c) {
  for (int ch = 0; ch < kCorrectionChannels; ++ch) {
    const int shift = channel_shift(ch);
    std::vector<std::int64_t>& field = f[ch];
    for (const Correction& k : c[ch]) field[k.pos] = wadd(field[k.pos], wshl(k.value, shift));
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
  const auto scales = output_scales(config);
  const auto to = outputs(out);
  for (int ch = 0; ch < kCorrectionChannels; ++ch) to[ch]->resize(f[ch].size());
  out.jacobian.resize(out.disp_xx.size());
  // Sample by sample, so any split of the samples gives the same floats.
  const std::size_t samples = f[ChannelId::height].size();
  const int parts = parallel ? kParallelParts : 1;
  run_jobs(parallel, parts, [&](int part) {
    const std::size_t begin = samples * part / parts, end = samples * (part + 1) / parts;
    for (int ch = 0; ch < kCorrectionChannels; ++ch)
      if (!f[ch].empty()) scale_fields(f[ch].data() + begin, end - begin, scales[ch], to[ch]->data() + begin);
    jacobian(out, begin, end);
  });
}

void to_float(const UnroundedFields& f, const Corrections& corrections, const StreamConfig& config,
              ReconstructedFrame& out, const ParallelFor& parallel) {
  const auto scales = output_scales(config);
  const auto to = outputs(out);
  std::vector<CorrectionSum> sums[kCorrectionChannels];
  for (int ch = 0; ch < kCorrectionChannels; ++ch) {
    to[ch]->resize(f.channels[ch].size());
    sums[ch] = summed(corrections[ch], channel_shift(ch));
  }
  out.jacobian.resize(out.disp_xx.size());
  const std::vector<StreamConfig::Lattice> lattices = config.lattices();
  const auto lattice_end = [](const StreamConfig::Lattice& l) { return l.samples_at + static_cast<std::size_t>(l.n) * l.n; };
  const std::size_t samples = f.channels[0].size();
  const int parts = parallel ? kParallelParts : 1;
  run_jobs(parallel, parts, [&](int part) {
    const std::size_t begin = samples * part / parts, end = samples * (part + 1) / parts;
    for (int ch = 0; ch < kCorrectionChannels; ++ch) {
      const std::vector<float>& x = f.channels[ch];
      if (x.empty()) continue;
      float* y = to[ch]->data();
      for (const StreamConfig::Lattice& l : lattices) {
        const std::size_t b = std::max(begin, l.samples_at), e = std::min(end, lattice_end(l));
        if (b < e) round_scale_fields(x.data() + b, e - b, synthesis_scale(l.n), scales[ch], y + b);
      }
      // The corrected samples of this part, again one by one through the integers.
      const auto first = std::lower_bound(sums[ch].begin(), sums[ch].end(), begin,
                                          [](const CorrectionSum& s, std::size_t at) { return s.pos < at; });
      std::size_t g = 0;
      for (auto k = first; k != sums[ch].end() && k->pos < end; ++k) {
        while (k->pos >= lattice_end(lattices[g])) ++g;
        const std::int64_t v = wadd(round_field(x[k->pos], synthesis_scale(lattices[g].n)), k->add);
        y[k->pos] = static_cast<float>(static_cast<double>(v) * scales[ch]);
      }
    }
    jacobian(out, begin, end);
  });
}

}  // namespace ocean::codec
