// The per-mode and per-point loops of a tick: advancing h(k, t), deriving the spectra of slopes,
// displacement and displacement gradient from it, and combining the gradient into the Jacobian.
// Each loop writes several spectra in one pass so h is read from memory as few times as possible.
// Built for SSE2 and AVX2 (picked once per process from the CPU); with -ffp-contract=off both round
// identically, so the choice never changes a bit of the frame.
#pragma once

#include "common/channels.hpp"
#include "mode_table.hpp"

#include <fftw3.h>

#include <cstddef>

namespace ocean::sim {

// h(k, t) for every mode, as the interleaved half spectrum c2r reads; with slope_x and slope_z
// non-null also i kx h and i kz h.
void advance_heights(const ModeTable& modes, double t, fftwf_complex* h, fftwf_complex* slope_x,
                     fftwf_complex* slope_z);

// disp_x = -i lambda kx/|k| h, disp_z = -i lambda kz/|k| h.
void derive_displacement(const ModeTable& modes, float lambda, const fftwf_complex* h, fftwf_complex* disp_x,
                         fftwf_complex* disp_z);

// Their derivatives: d_xx = lambda kx^2/|k| h, d_zz = lambda kz^2/|k| h, d_xz = lambda kx kz/|k| h.
void derive_displacement_gradient(const ModeTable& modes, float lambda, const fftwf_complex* h, fftwf_complex* d_xx,
                                  fftwf_complex* d_zz, fftwf_complex* d_xz);

// The rows of common/channels.hpp the kernels above compute, fused; any later row is derived
// alone by derive_channel.
inline constexpr int kFusedChannels = 8;
static_assert(kChannels[kFusedChannels - 1].name == "disp_xz", "the fused kernels compute the table's first rows");

// A row's spectrum from h by its kind and factor (common/channels.hpp), every mode on its own.
void derive_channel(const ModeTable& modes, const ChannelInfo& channel, float lambda, const fftwf_complex* h,
                    fftwf_complex* out);

// J = (1 + xx)(1 + zz) - xz^2 point by point; jacobian may be xx itself.
void combine_jacobian(const float* xx, const float* zz, const float* xz, float* jacobian, std::size_t count);

}  // namespace ocean::sim
