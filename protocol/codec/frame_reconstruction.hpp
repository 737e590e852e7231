// The steps encoder and decoder share to turn a predicted state plus a frame's corrections into
// the reconstruction and the next state, and the integer-to-float output conversion.
#pragma once

#include "chunk_body.hpp"
#include "modal_model.hpp"
#include "stream_config.hpp"
#include "tick.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace ocean::codec {

// What a client renders: floats in metres (height, displacement) and dimensionless slopes and
// derivatives, row-major z * n + x. Fields a stream does not carry are empty.
struct ReconstructedFrame {
  Tick tick = 0;
  Tick baseline = 0;      // the tick of the state it was decoded from; a key's own tick
  bool complete = false;  // all chunks arrived (only complete frames can be baselines)
  std::uint64_t shared_id = 0;  // nonzero: this very frame is shown by every decoder of a DecodeMemo that got it
  std::vector<float> height, slope_x, slope_z;
  // Choppy streams: horizontal displacement (choppiness applied, as the sim's), its derivatives
  // dDx/dx, dDz/dz, dDx/dz, and the Jacobian (1 + xx)(1 + zz) - xz^2 of the displaced grid,
  // which folds (foam) where it falls low.
  std::vector<float> disp_x, disp_z, disp_xx, disp_zz, disp_xz, jacobian;
};

// ReconstructedFrame's field of each channel (common/channels.hpp), in the table's order.
inline constexpr ChannelMembers<ReconstructedFrame, std::vector<float>> kReconstructedChannels = {
    &ReconstructedFrame::height, &ReconstructedFrame::slope_x, &ReconstructedFrame::slope_z,
    &ReconstructedFrame::disp_x, &ReconstructedFrame::disp_z,  &ReconstructedFrame::disp_xx,
    &ReconstructedFrame::disp_zz, &ReconstructedFrame::disp_xz};
constexpr const auto& channel_members(const ReconstructedFrame*) { return kReconstructedChannels; }

// fields += corrections (height and displacement in step/4 quanta, slopes and displacement
// derivatives in slope_step/4 quanta).
void apply_corrections(SampleFields& fields, const Corrections& corrections);

// The n x n spatial field (height units) of a frame's height corrections.
std::vector<std::int64_t> height_correction_field(std::size_t samples, const std::vector<Correction>& height);

// State of a key: X(t) = x << pos_shift and X(t-1) = X(t) - (v << vel_shift) on the key modes, 0
// elsewhere, conjugate partners filled in. `coefficients` is in key_modes() order.
ModalState key_state(const ModalModel& model, std::span<const KeyCoefficient> coefficients,
                     int pos_shift, int vel_shift);

// Exact output conversion: float(double(v) * step / 2^16), float(double(s) * slope_step / 2^12),
// displacement as heights with disp_step; the Jacobian in float from the float derivatives. With
// `parallel`, parts of the samples side by side (the same floats).
void to_float(const SampleFields& fields, const StreamConfig& config, ReconstructedFrame& out,
              const ParallelFor& parallel = {});

// The same floats from the fields before rounding and the frame's corrections: to_float of
// round_fields() plus apply_corrections(), in one pass and without the integer fields.
void to_float(const UnroundedFields& fields, const Corrections& corrections, const StreamConfig& config,
              ReconstructedFrame& out, const ParallelFor& parallel = {});

}  // namespace ocean::codec
