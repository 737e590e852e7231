// The two conversions between binary32 and integer fields, each over a whole frame, four values
// per AVX2 step where the CPU has it (the scalar loops do not vectorize: x86 converts between
// int64 and floating point only in AVX-512), with the scalar results.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::codec {

// Synthesis output to fields (CODEC.md 7.2): the integer nearest x * scale (scale = 2^-2L), ties to
// even, saturated at +-(2^51 - 1), NaN 0.
void round_fields(const float* x, std::size_t count, double scale, std::int64_t* out);

// Fields to output floats (CODEC.md 7.4): float(double(v) * scale).
void scale_fields(const std::int64_t* v, std::size_t count, double scale, float* out);

}  // namespace ocean::codec
