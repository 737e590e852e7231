// frame_hash(): a 64-bit FNV-1a digest of a frame's dimensions and the raw bytes of every field,
// so two processes can show they computed bit-identical frames.
#pragma once

#include "frame.hpp"

#include <cstdint>

namespace ocean::sim {

std::uint64_t frame_hash(const Frame& frame);

}  // namespace ocean::sim
