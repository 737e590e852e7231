// Encoder::chunk_frame: a frame's body cut into the fewest chunks whose payloads fit
// max_payload (CODEC.md 8), each independently decodable.
#include "encoder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ocean::codec {
namespace {

struct Piece {
  std::uint32_t begin, end;
  std::vector<std::uint8_t> body;
  BodyCost cost;
};

// The piece from `begin` with the largest end whose payload fits: grow geometrically from
// begin + guess, then bisect. Sizes are (nearly) monotone in the end; whatever is chosen was
// checked to fit. `size_of(b, e, body, cost)` encodes the range and returns its payload size.
template <typename SizeOf>
Piece largest_fitting(std::uint32_t begin, std::uint32_t total, std::uint32_t guess, std::size_t max_payload,
                      SizeOf&& size_of) {
  Piece best{begin, begin, {}, {}};
  std::vector<std::uint8_t> body;
  BodyCost cost;
  auto fits = [&](std::uint32_t end) {
    if (size_of(begin, end, body, cost) > max_payload) return false;
    best = {begin, end, std::move(body), cost};
    return true;
  };
  std::uint32_t lo = begin, hi = total + 1;
  std::uint32_t end = std::min(total, begin + std::max<std::uint32_t>(guess, 1));
  while (true) {
    if (!fits(end)) {
      hi = end;
      break;
    }
    lo = end;
    if (end == total) break;
    end = std::min(total, begin + 2 * (end - begin));
  }
  while (hi - lo > 1) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    if (fits(mid))
      lo = mid;
    else
      hi = mid;
  }
  return best;
}

}  // namespace

void Encoder::chunk_frame(EncodedFrame& frame, const BodyLayout& layout, const ChunkHeader& proto,
                          const std::vector<KeyCoefficient>& key_coefficients, const Corrections& corr) {
  const std::uint32_t total = layout.total();
  const ChunkView env{frame.id.tick, frame.key ? frame.id.tick : frame.base.tick, frame.key, 0, 1, {}};
  // Payload size for a range; the header does not depend on the envelope or the CRC value. A
  // single chunk covering the frame writes no range (ChunkHeader::whole): trials of the whole
  // range measure it that way too.
  auto size_of = [&](std::uint32_t b, std::uint32_t e, std::vector<std::uint8_t>& body, BodyCost& cost) {
    cost = {};
    body = encode_body(layout, b, e, key_coefficients, corr, &cost);
    ChunkHeader h = proto;
    h.item_begin = b;
    h.item_end = e;
    h.whole = b == 0 && e == total;
    return write_payload(h, env, config_.grid_log2(), body).size();
  };
  std::vector<Piece> pieces;
  std::uint32_t guess = layout.spectral_items ? 64 : total;
  for (std::uint32_t begin = 0; begin < total;) {
    Piece piece = largest_fitting(begin, total, guess, options_.max_payload, size_of);
    if (piece.end == begin)
      throw std::runtime_error("Encoder: one item does not fit max_payload = " + std::to_string(options_.max_payload));
    frame.stats.cost.key_bits += piece.cost.key_bits;
    frame.stats.cost.height_bits += piece.cost.height_bits;
    frame.stats.cost.slope_bits += piece.cost.slope_bits;
    frame.stats.cost.choppy_bits += piece.cost.choppy_bits;
    guess = piece.end - begin;
    begin = piece.end;
    pieces.push_back(std::move(piece));
  }
  if (pieces.size() > kMaxChunksPerFrame)
    throw std::runtime_error("Encoder: frame needs " + std::to_string(pieces.size()) + " chunks, more than " +
                             std::to_string(kMaxChunksPerFrame) + " (raise max_payload)");
  const auto count = static_cast<std::uint16_t>(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Chunk c;
    c.tick = env.tick;
    c.baseline = env.baseline;
    c.key = frame.key;
    c.index = static_cast<std::uint16_t>(i);
    c.count = count;
    ChunkHeader h = proto;
    h.item_begin = pieces[i].begin;
    h.item_end = pieces[i].end;
    h.whole = count == 1;
    c.payload = write_payload(h, view(c), config_.grid_log2(), pieces[i].body);
    frame.stats.payload_bytes += c.payload.size();
    frame.chunks.push_back(std::move(c));
  }
}

}  // namespace ocean::codec
