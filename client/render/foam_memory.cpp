#include "client/render/foam_memory.hpp"

#include <algorithm>

namespace ocean::render {

const std::vector<float>& FoamMemory::update(std::span<const float> jacobian, double dt_s) {
  if (memory_.size() != jacobian.size()) {
    memory_.assign(jacobian.begin(), jacobian.end());
    return memory_;
  }
  const float recover = recovery_per_s_ * static_cast<float>(std::clamp(dt_s, 0.0, 1.0));
  for (std::size_t i = 0; i < memory_.size(); ++i) memory_[i] = std::min(jacobian[i], memory_[i] + recover);
  return memory_;
}

}  // namespace ocean::render
