// The conversions between binary32 and integer fields, each over a whole frame, four int64
// values (eight int32 in round_scale_fields) per AVX2 step where the CPU has it (the scalar loops
// do not vectorize: x86 converts between int64 and floating point only in AVX-512), with the
// scalar results.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::codec {

// The inverse transform's 1 / n^2 on an n x n lattice: 2^-2L, exact.
inline double synthesis_scale(int n) { return 1.0 / (static_cast<double>(n) * n); }

// Synthesis output to fields (CODEC.md 7.2): the integer nearest x * scale (scale = 2^-2L), ties to
// even, saturated at +-(2^51 - 1), NaN 0.
void round_fields(const float* x, std::size_t count, double scale, std::int64_t* out);

// Fields to output floats (CODEC.md 7.4): float(double(v) * scale).
void scale_fields(const std::int64_t* v, std::size_t count, double scale, float* out);

// One sample of round_fields.
std::int64_t round_field(float x, double scale);

// round_fields then scale_fields without the integers between them: the same floats, with a
// quarter of the memory traffic (a decoder converts synthesis straight to what it shows).
void round_scale_fields(const float* x, std::size_t count, double round_scale, double out_scale, float* out);

}  // namespace ocean::codec
