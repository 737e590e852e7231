// ModalModel: the decoder's physics. The state is the pair (X(t-1), X(t)) of half-spectra of the
// height field in fixed point; every mode advances by X(t+1) = a(k) X(t) - X(t-1), a = 2 cos(w dt).
// Also synthesizes heights and spectral slopes from X(t) and folds spatial corrections back in.
#pragma once

#include "fixed_fft.hpp"
#include "stream_config.hpp"

#include <cstdint>
#include <vector>

namespace ocean::codec {

// Units (CODEC.md 2): heights in step / 2^16, slopes in slope_step / 2^12; a spectrum is the
// unnormalized DFT of a height field in those units.
inline constexpr int kHeightFracBits = 16;
inline constexpr int kSlopeFracBits = 12;
inline constexpr int kRecurrenceBits = 48;   // a(k) in Q48
inline constexpr int kSlopeCoefBits = 32;    // k-to-slope factors in Q32
inline constexpr int kHeightQuantumShift = 14;  // height corrections count step / 4 = 2^14 units
inline constexpr int kSlopeQuantumShift = 10;   // slope corrections count slope_step / 4 = 2^10 units

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

// Integer sample fields, row-major z * n + x.
struct SampleFields {
  std::vector<std::int64_t> height;            // step / 2^16 units
  std::vector<std::int64_t> slope_x, slope_z;  // slope_step / 2^12 units; empty without normals
};

class ModalModel {
 public:
  explicit ModalModel(const StreamConfig& config);

  int n() const { return n_; }
  int half_cols() const { return n_ / 2 + 1; }
  int half_size() const { return n_ * (n_ / 2 + 1); }
  bool normals() const { return normals_; }

  ModalState zero_state() const;

  // One tick forward, and `steps` ticks forward.
  void advance(ModalState& state) const;
  void advance(ModalState& state, std::uint64_t steps) const;

  // Heights (and slopes when streamed) of the field whose spectrum is `cur`.
  void synthesize(const HalfSpectrum& cur, SampleFields& out);

  // Half-spectrum of a real field (n x n, units as heights), made exactly Hermitian.
  void spectrum_of(const std::int64_t* field, HalfSpectrum& out);

  // Adds the spectrum of a spatial height correction to both X(t-1) and X(t): shifts the
  // position of every mode without giving it velocity.
  void add_correction(ModalState& state, const std::vector<std::int64_t>& correction_field);

  // Key-frame modes: the kx >= 0 half minus DC, the Nyquist row and column and the redundant
  // kx = 0 partners; indices into a HalfSpectrum, in transmission order.
  const std::vector<std::int32_t>& key_modes() const { return key_modes_; }
  // Fills the kx = 0 partners (rows n/2+1..n-1) from their conjugates after a key is loaded.
  void mirror_key_column(HalfSpectrum& s) const;

  std::int64_t recurrence_coef(int index) const { return a_[index]; }

 private:
  int n_;
  int log2n_;
  bool normals_;
  std::vector<std::int64_t> a_;       // Q48, per half-spectrum mode
  std::vector<std::int64_t> kx_coef_; // Q32 per column c in [0, n/2]
  std::vector<std::int64_t> kz_coef_; // Q32 per row r in [0, n)
  std::vector<std::int32_t> key_modes_;
  FixedFft fft_;
  std::vector<std::int64_t> z_re_, z_im_, w_re_, w_im_;  // n x n scratch
};

}  // namespace ocean::codec
