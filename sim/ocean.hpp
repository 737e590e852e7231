// Ocean: the Tessendorf spectral ocean. Owns h0(k), w(k) and the FFTW plans; evaluates frames
// at any time t. Pure: no clocks, no I/O, no globals; the frame depends only on (params, t).
// One Ocean serves one thread at a time; separate Oceans may run on separate threads.
#pragma once

#include "frame.hpp"
#include "sea_model.hpp"

#include <complex>
#include <memory>

namespace ocean::sim {

class Ocean {
 public:
  explicit Ocean(const SceneParams& params);  // throws ParamError
  ~Ocean();
  Ocean(Ocean&&) noexcept;
  Ocean& operator=(Ocean&&) noexcept;

  const SceneParams& params() const;

  // The full size_x x size_z frame at time t (seconds); throws ParamError for a non-finite t or
  // |t| beyond the limit the message states (1e9 s for ordinary scenes).
  void evaluate(double t, Frame& out, FrameRequest request = {});

  // An n_x x n_z frame (powers of two, 16 <= n <= size) made from the central n_x x n_z modes of the
  // same spectrum: the exact low-pass of the full frame, sampled every size/n-th point.
  void evaluate_band(double t, int n_x, int n_z, Frame& out, FrameRequest request = {});
  // Builds the n_x x n_z band now (its mode table and plan), so a first evaluate_band of it costs a
  // tick's work only: a server builds the next scene's bands ahead of its tick. Throws as evaluate_band.
  void prepare_band(int n_x, int n_z);

  // h(k, t) in metres of the wave with integer wavenumber (kx, kz) (cycles per patch) as the full
  // frame uses it, computed independently in double: h0(k) e^{-iwt} + conj(h0(-k)) e^{iwt} (the
  // mode drawn from P(k) travels along +k, downwind). 0 for DC and |kx| >= size_x/2, |kz| >= size_z/2.
  // The frame is height(x) = sum_k h(k, t) e^{i k.x}. For tests and exact predictors.
  std::complex<double> mode_amplitude(double t, int kx, int kz) const;

  // Expected height variance of the full frame (m^2): the sum of P(k) dkx dkz over its modes.
  double expected_variance() const;

  // Inverse FFTs that evaluate() runs for this request (1 height + 2 slopes + 5 choppy).
  int transform_count(FrameRequest request = {}) const;

  // Benchmark hook: only the FFTW executions of one full-grid evaluate(), into the same arrays
  // (`frame` must come from evaluate() with the same request); garbage in, garbage out.
  void execute_transforms_only(Frame& frame, FrameRequest request = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ocean::sim
