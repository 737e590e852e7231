#include "channel_pair.hpp"

#include <cstddef>

namespace ocean::codec {
namespace {

// One channel's value at half-spectrum mode h (row factor kz, column factor kx), CODEC.md 7.2;
// every operation in binary32, as written there.
template <ChannelKind K>
inline void channel_value(const float* g, float kx, float kz, std::size_t h, float hr, float hi, float& re, float& im) {
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
    re = g[h] * hi;
    im = -(g[h] * hr);
  } else {
    re = g[h] * hr;
    im = g[h] * hi;
  }
}

template <ChannelKind A, ChannelKind B>
void pack(const FloatSpectrum& x, const float* ga, const float* gb, float* z_re, float* z_im) {
  const int n = x.n, hc = n / 2 + 1;
  for (int r = 0; r < n; ++r) {
    const int rm = (n - r) % n;
    const float kz = x.kz[r];
    for (int c = 0; c < hc; ++c) {
      const std::size_t h = static_cast<std::size_t>(r) * hc + c;
      float xr, xi, yr, yi;
      channel_value<A>(ga, x.kx[c], kz, h, x.re[h], x.im[h], xr, xi);
      channel_value<B>(gb, x.kx[c], kz, h, x.re[h], x.im[h], yr, yi);
      const std::size_t at = static_cast<std::size_t>(r) * n + c;
      z_re[at] = xr - yi;
      z_im[at] = xi + yr;
      if (c > 0 && c < n / 2) {  // the conjugate partner -k
        const std::size_t mat = static_cast<std::size_t>(rm) * n + (n - c);
        z_re[mat] = xr + yi;
        z_im[mat] = yr - xi;
      }
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
