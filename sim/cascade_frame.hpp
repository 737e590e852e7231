// A cascaded stream's frame holds its cascades' samples one after the other, field by field (the
// codec's StreamConfig::cascades); each cascade's scene is model/cascade_scene.hpp's.
#pragma once

#include "frame.hpp"

namespace ocean::sim {

// Appends the fields of one cascade's frame to `out`'s.
void append_cascade_frame(Frame& out, const Frame& part);

}  // namespace ocean::sim
