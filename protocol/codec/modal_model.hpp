// ModalModel: the decoder's physics. The state is the pair (X(t-1), X(t)) of half-spectra of the
// height field in fixed point; every mode advances by X(t+1) = a(k) X(t) - X(t-1), a = 2 cos(w dt).
// Also synthesizes heights, spectral slopes and the choppy channels from X(t) (in binary32 since
// codec version 4: CODEC.md 7.2) and folds spatial corrections back in.
#pragma once

#include "channel_pair.hpp"
#include "chunk_body.hpp"
#include "fixed_fft.hpp"
#include "float_fft.hpp"
#include "parallel_for.hpp"
#include "stream_config.hpp"
#include "tick.hpp"
#include "wake_forcing.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace ocean::codec {

// Units (CODEC.md 2): heights in step / 2^16, slopes in slope_step / 2^12; a spectrum is the
// unnormalized DFT of a height field in those units. Displacement (codec version 3) counts like
// heights in disp_step, the Jacobian's inputs like slopes; corrections count quarter steps.
constexpr int frac_bits(ChannelUnit u) { return u == ChannelUnit::slope ? 12 : 16; }
constexpr int quantum_shift(ChannelUnit u) { return frac_bits(u) - 2; }
// What one unit of a channel's fields is in its own measure (metres, or a slope): step / 2^bits.
inline double unit_scale(const StreamConfig& config, ChannelUnit u) {
  return step_of(config, u) / static_cast<double>(1 << frac_bits(u));
}
inline constexpr int kHeightFracBits = frac_bits(ChannelUnit::height);
inline constexpr int kHeightQuantumShift = quantum_shift(ChannelUnit::height);
inline constexpr int kRecurrenceBits = 48;   // a(k) in Q48
// A delta's correction of the wake lattice counts as velocity by 1 / (this x lag) (CODEC.md 7.9):
// 1 tracks the hulls' forcing fastest but feeds every quantization error back as motion, and the
// free waves then keep needing corrections; 4 nearly silences them (test_wake_stream measures both).
inline constexpr std::uint64_t kWakeVelocityShare = 4;

// n rows x (n/2 + 1) columns (kx >= 0 half), row-major; the rest follows by X(-k) = conj X(k).
struct HalfSpectrum {
  std::vector<std::int64_t> re, im;
  bool operator==(const HalfSpectrum&) const = default;
};

struct ModalState {
  HalfSpectrum prev;  // X(t-1)
  HalfSpectrum cur;   // X(t)
  bool operator==(const ModalState&) const = default;
};

// Integer sample fields, row-major z * n + x, one per channel (common/channels.hpp), in units of
// 2^-16 height or displacement steps or 2^-12 slope steps; empty where the stream does not carry
// the channel. Choppy channels are scaled by the scene's choppiness lambda: D = -i lambda k/|k| X.
struct SampleFields : PerChannel<std::vector<std::int64_t>> {};

// The same channels before rounding: each the inverse transform's binary32 output, unscaled
// (CODEC.md 7.2), in coding order, empty where not streamed. A decoder keeps a frame so and
// rounds, corrects and converts it in one pass when it shows it (to_float, frame_reconstruction.hpp).
struct UnroundedFields {
  PerChannel<std::vector<float>> channels;
};

class ModalModel {
 public:
  explicit ModalModel(const StreamConfig& config);

  // The stream's lattices (StreamConfig::lattices): one, or one per cascade, their modes and
  // samples one after the other in every state and field.
  const std::vector<StreamConfig::Lattice>& lattices() const { return lattices_; }
  int n() const { return lattices_.front().n; }  // the first lattice's
  std::size_t samples() const { return samples_; }
  int half_size() const { return static_cast<int>(a_.size()); }
  bool normals() const { return normals_; }
  bool choppy() const { return choppy_; }

  ModalState zero_state() const;

  // Synthesis runs its transforms (one per pair of channels: up to four) through `parallel`, each
  // with scratch of its own; without one, one after the other.
  void set_parallel(ParallelFor parallel);

  // One tick forward, and `steps` ticks forward.
  void advance(ModalState& state) const;
  void advance(ModalState& state, std::uint64_t steps) const;
  // `from` advanced by `steps` ticks into `out` (another state, or `from` itself): a delta's state
  // needs no copy of its baseline first; parts of the modes side by side with `parallel`.
  // With `forcing`, the wake lattice's modes also take the hulls' pressure, the first step being
  // from tick `first` (CODEC.md 7.9).
  void advance(const ModalState& from, ModalState& out, std::uint64_t steps, const ParallelFor& parallel = {},
               WakeForcing* forcing = nullptr, Tick first = 0) const;

  // Heights (and slopes, displacement and its derivatives when streamed) of the field whose
  // spectrum is `cur`; `choppiness` is the lambda of the scene in force at the frame's tick.
  void synthesize(const HalfSpectrum& cur, double choppiness, SampleFields& out);
  // The same before rounding: round_fields() of each lattice's slice gives `out` above.
  void synthesize(const HalfSpectrum& cur, double choppiness, UnroundedFields& out);

  // Half-spectrum of a real field (every lattice's samples, units as heights), made exactly Hermitian.
  void spectrum_of(const std::int64_t* field, HalfSpectrum& out);

  // Adds the spectrum D of a spatial height correction to both X(t-1) and X(t): shifts the
  // position of every mode without giving it velocity. The wake lattice's modes, in a delta of
  // `lag` ticks (0 for a key: a shift as above), take D into X(t) and D - D / (4 lag) into X(t-1):
  // a miss that grew over the lag is partly motion the hulls gave, and the pair then carries that
  // share of it (CODEC.md 7.9).
  void add_correction(ModalState& state, const std::vector<std::int64_t>& correction_field, std::uint64_t lag);

  // Key-frame modes: the kx >= 0 half minus DC, the Nyquist row and column and the redundant
  // kx = 0 partners; indices into a HalfSpectrum, in transmission order.
  const std::vector<std::int32_t>& key_modes() const { return key_modes_; }
  // Fills the kx = 0 partners (rows n/2+1..n-1 of each lattice) from their conjugates after a key is loaded.
  void mirror_key_column(HalfSpectrum& s) const;

  std::int64_t recurrence_coef(int index) const { return a_[index]; }
  // Where the wake lattice's modes start (modes() when the stream has none).
  std::size_t wake_modes_at() const { return wake_at_; }

 private:
  struct SynthesisChannel {
    int index;  // coding order
    ChannelKind kind;
    const float* factor;  // per mode of the whole stream; null for height and slopes
  };
  int plan_channels(double choppiness, UnroundedFields& out, std::vector<std::int64_t>* const* rounded,
                    SynthesisChannel* channels);
  // G of every factored row the stream carries, in float for this choppiness (CODEC.md 7.2).
  void build_factors(double choppiness);
  // Both synthesize()s: `rounded` null, or the SampleFields' channels in coding order.
  void synthesize_channels(const HalfSpectrum& cur, double choppiness, UnroundedFields& out,
                           std::vector<std::int64_t>* const* rounded);
  // One inverse FFT of two channels packed as A + iB (channel_pair.hpp) of one lattice, in place
  // in its slice of their fields (b_out null when B is none).
  struct PairScratch;
  void synthesize_pair(PairScratch& scratch, const FloatSpectrum& x, ChannelSource a, ChannelSource b,
                       float* a_out, float* b_out) const;
  // spectrum_of() for lattice g: its samples of `field` into its modes of `out`.
  void lattice_spectrum(std::size_t g, const std::int64_t* field, HalfSpectrum& out);

  std::vector<StreamConfig::Lattice> lattices_;
  std::size_t samples_ = 0;
  bool normals_;
  bool choppy_;
  PerChannel<double> unit_factor_;  // height units to each channel's units
  std::vector<std::int64_t> a_;  // Q48, per half-spectrum mode
  // The wake lattice's damped recurrence X(t+1) = a X(t) - b X(t-1): b in Q48 per mode from wake_at_.
  std::size_t wake_at_ = 0;
  std::vector<std::int64_t> b_;
  std::vector<double> alpha_, beta_;  // per wake mode: the forcing's weights of P(t-1) and P(t)
  void advance_forced_wake(const ModalState& from, ModalState& out, std::uint64_t steps, WakeForcing& forcing,
                           Tick first) const;

 public:
  // The wake lattice's modes alone (count: modes() - wake_modes_at()), as a history of the wake
  // keeps them (CODEC.md 7.9): `steps` ticks from `first`, forced by the hulls only during ticks
  // in [force_from, force_until) (signed ticks).
  struct WakeSpan {
    std::int64_t *prev_re, *prev_im, *cur_re, *cur_im;
  };
  void step_wake(WakeSpan state, std::uint64_t steps, Tick first, WakeForcing* forcing, std::int64_t force_from,
                 std::int64_t force_until) const;

 private:
  std::vector<std::int32_t> key_modes_;
  // The channels with a factor G (ChannelInfo::gx, gz): G per half-spectrum mode (0 at DC and
  // Nyquist), and in float with the choppiness they were last built for and the channel's units.
  PerChannel<std::vector<double>> ratio_;
  PerChannel<std::vector<float>> channel_factor_;
  double factor_choppiness_ = -1.0;
  std::vector<float> h_re_, h_im_;  // X(t) in binary32
  UnroundedFields unrounded_;  // what synthesize(SampleFields) rounds
  std::vector<std::int64_t> z_re_, z_im_;  // the largest lattice's n x n scratch
  // What one transform of synthesis works in besides its channels' slices.
  struct PairScratch {
    explicit PairScratch(int n) : fft(n), discard(static_cast<std::size_t>(n) * n) {}
    FloatFft fft;
    std::vector<float> discard;  // the imaginary part when B is none
  };
  // Per lattice: its slope factors per column and row (i kx, i kz to slope units), and transforms.
  struct Grid {
    explicit Grid(int n) : fft(n) {}
    std::vector<float> kx, kz;
    FixedFft fft;  // spectrum_of: corrections enter the integer state exactly
    std::vector<std::unique_ptr<PairScratch>> pair_scratch;  // one, or one per pair with parallel_
  };
  std::vector<std::unique_ptr<Grid>> grids_;  // as lattices_
  ParallelFor parallel_;
};

}  // namespace ocean::codec
