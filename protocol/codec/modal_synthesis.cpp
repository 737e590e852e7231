// The synthesis of a frame's channels from the state (CODEC.md 7.2): heights, slopes and the
// choppy channels in pairs, lattice by lattice, and the half spectrum of a lattice's field.
#include "modal_model.hpp"

#include "channel_pair.hpp"
#include "fft_bin.hpp"
#include "field_conversion.hpp"
#include "fixed_point.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ocean::codec {
namespace {

// A state value as binary32 (CODEC.md 7.2): through double, as every language can.
float to_binary32(std::int64_t v) { return static_cast<float>(static_cast<double>(v)); }

}  // namespace

void ModalModel::synthesize_pair(PairScratch& scratch, const FloatSpectrum& x, ChannelSource a, ChannelSource b,
                                 float* a_out, float* b_out) const {
  float* b_or_discard = b_out ? b_out : scratch.discard.data();
  pack_channel_pair(x, a, b, a_out, b_or_discard);
  scratch.fft.inverse_2d(a_out, b_or_discard);
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, UnroundedFields& out) {
  synthesize_channels(cur, choppiness, out, nullptr);
}

void ModalModel::synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out) {
  std::vector<std::int64_t>* fields[kCorrectionChannels];
  for (int ch = 0; ch < kCorrectionChannels; ++ch) fields[ch] = &out[ch];
  synthesize_channels(cur, choppiness, unrounded_, fields);
}

// The channels the stream carries that have a transform this frame, in coding order, sized; the
// others cleared (not streamed) or zeroed. They are synthesized in consecutive pairs (CODEC.md
// 7.2), lattice by lattice.
int ModalModel::plan_channels(double choppiness, UnroundedFields& out, std::vector<std::int64_t>* const* rounded,
                              SynthesisChannel* channels) {
  int count = 0;
  const std::size_t nn = samples_;
  // A channel without a transform: not streamed (cleared), or exactly 0 everywhere.
  const auto without_transform = [&](int index, bool zeros) {
    out.channels[index].assign(zeros ? nn : 0, 0.0f);
    if (rounded) rounded[index]->assign(zeros ? nn : 0, 0);
  };
  if (choppiness != factor_choppiness_) build_factors(choppiness);
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const ChannelInfo& info = kChannels[ch];
    // At choppiness 0 a factor with lambda is 0, so the field is exactly 0.
    if (!carried(info, normals_, choppy_)) without_transform(ch, false);
    else if (factored(info) && info.factor.choppy && choppiness == 0.0) without_transform(ch, true);
    else channels[count++] = {ch, info.kind, factored(info) ? channel_factor_[ch].data() : nullptr};
  }
  for (int i = 0; i < count; ++i) {
    out.channels[channels[i].index].resize(nn);
    if (rounded) rounded[channels[i].index]->resize(nn);
  }
  return count;
}

void ModalModel::synthesize_channels(const HalfSpectrum& cur, double choppiness, UnroundedFields& out,
                                     std::vector<std::int64_t>* const* rounded) {
  const std::size_t m = a_.size();
  h_re_.resize(m);
  h_im_.resize(m);
  for (std::size_t h = 0; h < m; ++h) {
    h_re_[h] = to_binary32(cur.re[h]);
    h_im_[h] = to_binary32(cur.im[h]);
  }
  SynthesisChannel channels[kCorrectionChannels];
  const int count = plan_channels(choppiness, out, rounded, channels);
  for (std::size_t g = 0; g < grids_.size(); ++g) {
    const StreamConfig::Lattice& l = lattices_[g];
    Grid& grid = *grids_[g];
    const FloatSpectrum x{l.n, h_re_.data() + l.modes_at, h_im_.data() + l.modes_at, grid.kx.data(), grid.kz.data()};
    const auto source = [&](const SynthesisChannel& c) {
      return ChannelSource{c.kind, c.factor ? c.factor + l.modes_at : nullptr};
    };
    const std::size_t lattice_samples = static_cast<std::size_t>(l.n) * l.n;
    const double scale = synthesis_scale(l.n);
    const auto slice = [&](const SynthesisChannel& c) { return out.channels[c.index].data() + l.samples_at; };
    const bool spread = grid.pair_scratch.size() > 1;
    run_jobs(spread ? parallel_ : ParallelFor{}, (count + 1) / 2, [&](int pair) {
      const SynthesisChannel& a = channels[2 * pair];
      const SynthesisChannel* b = 2 * pair + 1 < count ? &channels[2 * pair + 1] : nullptr;
      synthesize_pair(*grid.pair_scratch[spread ? pair : 0], x, source(a), b ? source(*b) : ChannelSource{}, slice(a),
                      b ? slice(*b) : nullptr);
      if (!rounded) return;
      for (const SynthesisChannel* c : {&a, b})
        if (c) round_fields(slice(*c), lattice_samples, scale, rounded[c->index]->data() + l.samples_at);
    });
  }
}

void ModalModel::spectrum_of(const std::int64_t* field, HalfSpectrum& out) {
  out.re.resize(a_.size());
  out.im.resize(a_.size());
  for (std::size_t g = 0; g < grids_.size(); ++g) lattice_spectrum(g, field, out);
}

void ModalModel::lattice_spectrum(std::size_t g, const std::int64_t* all_fields, HalfSpectrum& all) {
  const StreamConfig::Lattice& l = lattices_[g];
  const int n = l.n, hc = n / 2 + 1;
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  const std::int64_t* field = all_fields + l.samples_at;
  for (std::size_t i = 0; i < nn; ++i) {
    z_re_[i] = field[i];
    z_im_[i] = 0;
  }
  grids_[g]->fft.forward_2d(z_re_.data(), z_im_.data());
  std::int64_t* re = all.re.data() + l.modes_at;
  std::int64_t* im = all.im.data() + l.modes_at;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < hc; ++c) {
      re[r * hc + c] = z_re_[static_cast<std::size_t>(r) * n + c];
      im[r * hc + c] = z_im_[static_cast<std::size_t>(r) * n + c];
    }
  // Columns kx = 0 and kx = n/2 hold both k and -k: take the rows up to n/2 as the truth.
  for (int c : {0, n / 2}) {
    for (int r = n / 2 + 1; r < n; ++r) {
      re[r * hc + c] = re[(n - r) * hc + c];
      im[r * hc + c] = -im[(n - r) * hc + c];
    }
    im[c] = 0;
    im[(n / 2) * hc + c] = 0;
  }
}

}  // namespace ocean::codec
