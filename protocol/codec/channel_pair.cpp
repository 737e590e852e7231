#include "channel_pair.hpp"

#include <cstddef>

namespace ocean::codec {
namespace {

// One channel's value at column c of a half-spectrum row (row factor kz, column factor kx, g the
// row's choppy factors), CODEC.md 7.2; every operation in binary32, as written there.
template <ChannelKind K>
inline void channel_value(const float* g, float kx, float kz, int c, float hr, float hi, float& re, float& im) {
  if constexpr (K == ChannelKind::none) {
    re = 0.0f;
    im = 0.0f;
  } else if constexpr (K == ChannelKind::height) {
    re = hr;
    im = hi;
  } else if constexpr (K == ChannelKind::slope_x) {
    re = -(kx * hi);
    im = kx * hr;
  } else if constexpr (K == ChannelKind::slope_z) {
    re = -(kz * hi);
    im = kz * hr;
  } else if constexpr (K == ChannelKind::disp) {
    re = g[c] * hi;
    im = -(g[c] * hr);
  } else {
    re = g[c] * hr;
    im = g[c] * hi;
  }
}

// Row by row: first the row's half-spectrum columns, then the conjugate partners of its inner
// columns, written from the end of the mirrored row. Each loop has one kind of store, so the
// compiler runs it in vector lanes (the same binary32 operations, element by element); one loop
// writing both, as CODEC.md states it, ran scalar and took a fifth of a frame's decode.
template <ChannelKind A, ChannelKind B>
void pack(const FloatSpectrum& x, const float* ga, const float* gb, float* z_re, float* z_im) {
  const int n = x.n, hc = n / 2 + 1;
  for (int r = 0; r < n; ++r) {
    const int rm = (n - r) % n;
    const float kz = x.kz[r];
    const std::size_t h0 = static_cast<std::size_t>(r) * hc;
    const float* re = x.re + h0;
    const float* im = x.im + h0;
    const float* fa = ga ? ga + h0 : nullptr;
    const float* fb = gb ? gb + h0 : nullptr;
    float* row_re = z_re + static_cast<std::size_t>(r) * n;
    float* row_im = z_im + static_cast<std::size_t>(r) * n;
    for (int c = 0; c < hc; ++c) {
      float xr, xi, yr, yi;
      channel_value<A>(fa, x.kx[c], kz, c, re[c], im[c], xr, xi);
      channel_value<B>(fb, x.kx[c], kz, c, re[c], im[c], yr, yi);
      row_re[c] = xr - yi;
      row_im[c] = xi + yr;
    }
    float* mirror_re = z_re + static_cast<std::size_t>(rm) * n;
    float* mirror_im = z_im + static_cast<std::size_t>(rm) * n;
    for (int c = 1; c < n / 2; ++c) {
      float xr, xi, yr, yi;
      channel_value<A>(fa, x.kx[c], kz, c, re[c], im[c], xr, xi);
      channel_value<B>(fb, x.kx[c], kz, c, re[c], im[c], yr, yi);
      mirror_re[n - c] = xr + yi;
      mirror_im[n - c] = yr - xi;
    }
  }
}

using PackFn = void (*)(const FloatSpectrum&, const float*, const float*, float*, float*);

template <ChannelKind A>
PackFn pack_for(ChannelKind b) {
  switch (b) {
    case ChannelKind::none: return pack<A, ChannelKind::none>;
    case ChannelKind::height: return pack<A, ChannelKind::height>;
    case ChannelKind::slope_x: return pack<A, ChannelKind::slope_x>;
    case ChannelKind::slope_z: return pack<A, ChannelKind::slope_z>;
    case ChannelKind::disp: return pack<A, ChannelKind::disp>;
    case ChannelKind::derivative: return pack<A, ChannelKind::derivative>;
  }
  return nullptr;
}

PackFn pack_for(ChannelKind a, ChannelKind b) {
  switch (a) {
    case ChannelKind::none: return pack_for<ChannelKind::none>(b);
    case ChannelKind::height: return pack_for<ChannelKind::height>(b);
    case ChannelKind::slope_x: return pack_for<ChannelKind::slope_x>(b);
    case ChannelKind::slope_z: return pack_for<ChannelKind::slope_z>(b);
    case ChannelKind::disp: return pack_for<ChannelKind::disp>(b);
    case ChannelKind::derivative: return pack_for<ChannelKind::derivative>(b);
  }
  return nullptr;
}

}  // namespace

void pack_channel_pair(const FloatSpectrum& x, ChannelSource a, ChannelSource b, float* z_re, float* z_im) {
  pack_for(a.kind, b.kind)(x, a.factor, b.factor, z_re, z_im);
}

}  // namespace ocean::codec
