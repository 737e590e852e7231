// FNV-1a over n_x, n_z and each field's length and bytes, in declaration order.
#include "frame_hash.hpp"

#include "common/fnv1a.hpp"

#include <cstddef>
#include <cstring>
#include <vector>

namespace ocean::sim {
namespace {

std::uint64_t mix_bytes(std::uint64_t h, const void* data, std::size_t size) { return common::fnv1a(data, size, h); }

std::uint64_t mix_field(std::uint64_t h, const std::vector<float>& field) {
  const std::uint64_t count = field.size();
  h = mix_bytes(h, &count, sizeof count);
  return mix_bytes(h, field.data(), field.size() * sizeof(float));
}

}  // namespace

std::uint64_t frame_hash(const Frame& f) {
  std::uint64_t h = common::kFnvOffset;
  const std::int32_t dims[2] = {f.n_x, f.n_z};
  h = mix_bytes(h, dims, sizeof dims);
  for (const std::vector<float>* field : {&f.height, &f.slope_x, &f.slope_z, &f.disp_x, &f.disp_z, &f.jacobian})
    h = mix_field(h, *field);
  return h;
}

}  // namespace ocean::sim
