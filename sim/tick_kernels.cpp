// Straight loops the compiler vectorises; target_clones adds an AVX2 build of each (no FMA, so
// every build rounds identically). Multiplying by kx or kz, or by their squares over |k|, keeps
// h(0, -kz) = conj(h(0, kz)) exact: negating kz negates or keeps each factor exactly in float.
#include "tick_kernels.hpp"

#include "phase_sincos.hpp"

#include <cfloat>
#include <cmath>

namespace ocean::sim {
namespace {

#if defined(__x86_64__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define OCEAN_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define OCEAN_VECTOR_CLONES
#endif

// The loops stream up to nine arrays, more than GCC will check for overlap at run time before it
// vectorises; they never overlap (separate allocations), which this tells it.
#if defined(__GNUC__) && !defined(__clang__)
#define OCEAN_NO_ALIAS _Pragma("GCC ivdep")
#else
#define OCEAN_NO_ALIAS
#endif

// 1/|k|, finite at k = 0 (where h is 0, so every factor times h stays 0 instead of NaN); FLT_MIN
// vanishes against every other |k|^2, which is at least (2 pi / 1e6 m)^2.
inline float inverse_length(float kx, float kz) { return 1.0f / std::sqrt(kx * kx + kz * kz + FLT_MIN); }

std::size_t row_start(const ModeTable& t, int row) { return static_cast<std::size_t>(row) * t.columns; }

// Interleaved (re, im) views of the half spectra.
float* floats(fftwf_complex* c) { return reinterpret_cast<float*>(c); }
const float* floats(const fftwf_complex* c) { return reinterpret_cast<const float*>(c); }

}  // namespace

namespace {

template <bool Slopes>
[[gnu::always_inline]] inline void advance_rows(const ModeTable& modes, double t, fftwf_complex* hc,
                                                fftwf_complex* slope_x, fftwf_complex* slope_z) {
  const float* __restrict kx = modes.kx.data();
  for (int j = 0; j < modes.n_z; ++j) {
    const std::size_t row = row_start(modes, j);
    const float kz = modes.kz[j];
    const double* __restrict omega = modes.omega.data() + row;
    const float* __restrict sum_re = modes.sum_re.data() + row;
    const float* __restrict sum_im = modes.sum_im.data() + row;
    const float* __restrict diff_re = modes.diff_re.data() + row;
    const float* __restrict diff_im = modes.diff_im.data() + row;
    float* __restrict h = floats(hc) + 2 * row;
    float* __restrict sx = Slopes ? floats(slope_x) + 2 * row : nullptr;
    float* __restrict sz = Slopes ? floats(slope_z) + 2 * row : nullptr;
    OCEAN_NO_ALIAS
    for (int i = 0; i < modes.columns; ++i) {
      const SinCos e = phase_sincos(omega[i] * t);
      const float re = sum_re[i] * e.cos + diff_im[i] * e.sin;
      const float im = sum_im[i] * e.cos - diff_re[i] * e.sin;
      h[2 * i] = re;
      h[2 * i + 1] = im;
      if constexpr (Slopes) {  // i k h = (-k im, k re)
        sx[2 * i] = -kx[i] * im;
        sx[2 * i + 1] = kx[i] * re;
        sz[2 * i] = -kz * im;
        sz[2 * i + 1] = kz * re;
      }
    }
  }
}

// The kx = 0 column is its own mirror: h(0, -kz) = conj(h(0, kz)) must hold exactly for c2r,
// whatever the rounding of the two independent evaluations. Also right for i kz h.
void mirror_first_column(const ModeTable& modes, fftwf_complex* c) {
  for (int j = 1; j < modes.n_z / 2; ++j) {
    const fftwf_complex& up = c[row_start(modes, j)];
    fftwf_complex& down = c[row_start(modes, modes.n_z - j)];
    down[0] = up[0];
    down[1] = -up[1];
  }
}

}  // namespace

OCEAN_VECTOR_CLONES
void advance_heights(const ModeTable& modes, double t, fftwf_complex* h, fftwf_complex* slope_x,
                     fftwf_complex* slope_z) {
  if (slope_x && slope_z) {
    advance_rows<true>(modes, t, h, slope_x, slope_z);
    mirror_first_column(modes, slope_x);
    mirror_first_column(modes, slope_z);
  } else {
    advance_rows<false>(modes, t, h, nullptr, nullptr);
  }
  mirror_first_column(modes, h);
}

OCEAN_VECTOR_CLONES
void derive_displacement(const ModeTable& modes, float lambda, const fftwf_complex* hc, fftwf_complex* disp_x,
                         fftwf_complex* disp_z) {
  const float* __restrict kx = modes.kx.data();
  for (int j = 0; j < modes.n_z; ++j) {
    const std::size_t row = row_start(modes, j);
    const float kz = modes.kz[j];
    const float* __restrict h = floats(hc) + 2 * row;
    float* __restrict dx = floats(disp_x) + 2 * row;
    float* __restrict dz = floats(disp_z) + 2 * row;
    OCEAN_NO_ALIAS
    for (int i = 0; i < modes.columns; ++i) {  // -i g h = (g im, -g re)
      const float ik = inverse_length(kx[i], kz);
      const float gx = lambda * kx[i] * ik, gz = lambda * kz * ik;
      const float re = h[2 * i], im = h[2 * i + 1];
      dx[2 * i] = gx * im;
      dx[2 * i + 1] = -gx * re;
      dz[2 * i] = gz * im;
      dz[2 * i + 1] = -gz * re;
    }
  }
}

OCEAN_VECTOR_CLONES
void derive_displacement_gradient(const ModeTable& modes, float lambda, const fftwf_complex* hc, fftwf_complex* d_xx,
                                  fftwf_complex* d_zz, fftwf_complex* d_xz) {
  const float* __restrict kx = modes.kx.data();
  for (int j = 0; j < modes.n_z; ++j) {
    const std::size_t row = row_start(modes, j);
    const float kz = modes.kz[j];
    const float* __restrict h = floats(hc) + 2 * row;
    float* __restrict xx = floats(d_xx) + 2 * row;
    float* __restrict zz = floats(d_zz) + 2 * row;
    float* __restrict xz = floats(d_xz) + 2 * row;
    OCEAN_NO_ALIAS
    for (int i = 0; i < modes.columns; ++i) {
      const float lik = lambda * inverse_length(kx[i], kz);
      const float gxx = lik * kx[i] * kx[i], gzz = lik * kz * kz, gxz = lik * kx[i] * kz;
      const float re = h[2 * i], im = h[2 * i + 1];
      xx[2 * i] = gxx * re;
      xx[2 * i + 1] = gxx * im;
      zz[2 * i] = gzz * re;
      zz[2 * i + 1] = gzz * im;
      xz[2 * i] = gxz * re;
      xz[2 * i + 1] = gxz * im;
    }
  }
}

void derive_channel(const ModeTable& modes, const ChannelInfo& channel, float lambda, const fftwf_complex* hc,
                    fftwf_complex* out) {
  for (int j = 0; j < modes.n_z; ++j) {
    const std::size_t row = row_start(modes, j);
    const float kz = modes.kz[j];
    const float* h = floats(hc) + 2 * row;
    float* o = floats(out) + 2 * row;
    for (int i = 0; i < modes.columns; ++i) {
      const float kx = modes.kx[i], inv_k = inverse_length(kx, kz);
      const float re = h[2 * i], im = h[2 * i + 1];
      float g = 1.0f;  // i g h: the slopes' kinds; -i g h: disp; g h: height and derivative
      if (factored(channel)) g = channel_factor(channel.factor, lambda, kx, kz, 1.0f / inv_k, inv_k);
      else if (channel.kind == ChannelKind::slope_x) g = kx;
      else if (channel.kind == ChannelKind::slope_z) g = kz;
      const bool times_i = channel.kind == ChannelKind::slope_x || channel.kind == ChannelKind::slope_z;
      if (times_i || channel.kind == ChannelKind::disp) {
        const float s = times_i ? g : -g;  // i s h = (-s im, s re)
        o[2 * i] = -s * im;
        o[2 * i + 1] = s * re;
      } else {
        o[2 * i] = g * re;
        o[2 * i + 1] = g * im;
      }
    }
  }
}

OCEAN_VECTOR_CLONES
void combine_jacobian(const float* xx, const float* __restrict zz, const float* __restrict xz, float* jacobian,
                      std::size_t count) {
  OCEAN_NO_ALIAS
  for (std::size_t i = 0; i < count; ++i) jacobian[i] = (1.0f + xx[i]) * (1.0f + zz[i]) - xz[i] * xz[i];
}

}  // namespace ocean::sim
