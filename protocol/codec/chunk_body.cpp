// Body coding (CODEC.md 6): context-modelled key coefficients, then per channel a count and
// (gap, value) pairs of corrections inside the chunk's sample range.
#include "chunk_body.hpp"

#include "range_coder.hpp"

#include <algorithm>
#include <array>
#include <memory>

namespace ocean::codec {
namespace {

constexpr int kContexts = 32;

int bit_length(std::uint64_t v) {
  int b = 0;
  while (v) {
    ++b;
    v >>= 1;
  }
  return b;
}

std::uint64_t magnitude(std::int64_t v) {
  return v < 0 ? static_cast<std::uint64_t>(-(v + 1)) + 1 : static_cast<std::uint64_t>(v);
}

int context_of(std::int64_t a, std::int64_t b) {
  return std::min(kContexts - 1, bit_length(magnitude(a) + magnitude(b)));
}

// All adaptive state of one body; fresh for every chunk.
struct Models {
  std::array<SIntModel, kContexts> x, v;
  UIntModel count, gap;
  std::array<SIntModel, kCorrectionChannels> value;  // one per channel, in coding order
};

struct SampleRange {
  std::uint32_t begin, end;  // sample indices
};

SampleRange samples_of(const BodyLayout& l, std::uint32_t begin, std::uint32_t end) {
  const std::uint32_t s = l.spectral_items;
  return {std::max(begin, s) - s, end > s ? end - s : 0};
}

void encode_channel(RangeEncoder& rc, Models& m, int ch, const std::vector<Correction>& list, SampleRange r) {
  auto lo = std::lower_bound(list.begin(), list.end(), r.begin, [](const Correction& c, std::uint32_t p) { return c.pos < p; });
  auto hi = std::lower_bound(lo, list.end(), r.end, [](const Correction& c, std::uint32_t p) { return c.pos < p; });
  encode_uint(rc, m.count, static_cast<std::uint64_t>(hi - lo));
  std::int64_t prev = static_cast<std::int64_t>(r.begin) - 1;
  for (auto it = lo; it != hi; ++it) {
    encode_uint(rc, m.gap, static_cast<std::uint64_t>(it->pos - prev - 1));
    encode_nonzero(rc, m.value[ch], it->value);
    prev = it->pos;
  }
}

bool decode_channel(RangeDecoder& rc, Models& m, int ch, std::vector<Correction>& list, SampleRange r) {
  std::uint64_t count;
  if (!decode_uint(rc, m.count, count) || count > r.end - r.begin) return false;
  list.reserve(count);
  std::uint64_t next = r.begin;  // smallest position the next correction may take
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint64_t gap;
    std::int64_t value;
    if (!decode_uint(rc, m.gap, gap) || gap >= r.end - next) return false;
    if (!decode_nonzero(rc, m.value[ch], value) || value > kMaxCorrection || value < -kMaxCorrection) return false;
    const std::uint64_t pos = next + gap;
    list.push_back({static_cast<std::uint32_t>(pos), static_cast<std::int32_t>(value)});
    next = pos + 1;
  }
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_body(const BodyLayout& layout, std::uint32_t begin, std::uint32_t end,
                                      std::span<const KeyCoefficient> key, const Corrections& corr,
                                      BodyCost* cost) {
  RangeEncoder rc(cost != nullptr);
  auto m = std::make_unique<Models>();
  const std::uint32_t spec_end = std::min(end, layout.spectral_items);
  std::int64_t pr = 0, pi = 0;
  for (std::uint32_t i = begin; i < spec_end; ++i) {
    const KeyCoefficient& k = key[i];
    const int cx = context_of(pr, pi);
    encode_sint(rc, m->x[cx], k.xr);
    encode_sint(rc, m->x[cx], k.xi);
    const int cv = context_of(k.xr, k.xi);
    encode_sint(rc, m->v[cv], k.vr);
    encode_sint(rc, m->v[cv], k.vi);
    pr = k.xr;
    pi = k.xi;
  }
  const double after_key = rc.cost_bits();
  if (end > layout.spectral_items) {
    const SampleRange r = samples_of(layout, begin, end);
    double group_bits[3] = {};  // what each ChannelGroup's channels cost
    for (int ch = 0; ch < kCorrectionChannels; ++ch) {
      const ChannelInfo& info = kChannels[ch];
      if (!carried(info, layout.normals, layout.choppy)) continue;
      const double before = rc.cost_bits();
      encode_channel(rc, *m, ch, corr[ch], r);
      group_bits[static_cast<int>(info.group)] += rc.cost_bits() - before;
    }
    if (cost) {
      cost->height_bits += group_bits[static_cast<int>(ChannelGroup::always)];
      cost->slope_bits += group_bits[static_cast<int>(ChannelGroup::normals)];
      cost->choppy_bits += group_bits[static_cast<int>(ChannelGroup::choppy)];
    }
  }
  if (cost) cost->key_bits += after_key;
  return rc.finish();
}

bool decode_body(const BodyLayout& layout, std::uint32_t begin, std::uint32_t end,
                 std::span<const std::uint8_t> body, DecodedBody& out) {
  RangeDecoder rc(body);
  auto m = std::make_unique<Models>();
  out.key.clear();
  out.corrections = {};
  const std::uint32_t spec_end = std::min(end, layout.spectral_items);
  std::int64_t pr = 0, pi = 0;
  for (std::uint32_t i = begin; i < spec_end; ++i) {
    KeyCoefficient k;
    const int cx = context_of(pr, pi);
    if (!decode_sint(rc, m->x[cx], k.xr) || !decode_sint(rc, m->x[cx], k.xi)) return false;
    const int cv = context_of(k.xr, k.xi);
    if (!decode_sint(rc, m->v[cv], k.vr) || !decode_sint(rc, m->v[cv], k.vi)) return false;
    out.key.push_back(k);
    pr = k.xr;
    pi = k.xi;
  }
  if (end > layout.spectral_items) {
    const SampleRange r = samples_of(layout, begin, end);
    for (int ch = 0; ch < kCorrectionChannels; ++ch)
      if (carried(kChannels[ch], layout.normals, layout.choppy) && !decode_channel(rc, *m, ch, out.corrections[ch], r))
        return false;
  }
  return true;
}

}  // namespace ocean::codec
