#include "cascade_frame.hpp"

namespace ocean::sim {

void append_cascade_frame(Frame& out, const Frame& part) {
  for (const auto field : kFrameFields) (out.*field).insert((out.*field).end(), (part.*field).begin(), (part.*field).end());
}

}  // namespace ocean::sim
