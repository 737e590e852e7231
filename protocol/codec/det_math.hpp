// Deterministic elementary functions for the codec's coefficient tables: built from + - * / and
// sqrt in double only (all correctly rounded by IEEE 754), evaluated in a fixed order, so every
// CPU and compiler gets the same bits (compile with -ffp-contract=off). Not for hot loops.
#pragma once

#include <cstdint>

namespace ocean::codec {

inline constexpr double kTwoPi = 6.283185307179586;  // nearest double to 2 pi

double det_cos(double x);
double det_sin(double x);
double det_exp_neg(double y);  // e^-y for y >= 0
double det_tanh(double x);     // x >= 0

// w = sqrt(g k tanh(k depth)); depth_m <= 0 means deep water (tanh = 1).
double det_angular_frequency(double k, double gravity, double depth_m);

// floor(x * 2^q + 1/2) as int64; |x * 2^q| must stay below 2^62.
std::int64_t to_fixed(double x, int q);

}  // namespace ocean::codec
