// CodecStream: a small real codec stream (16 x 16 grid with normals, a synthetic ocean) shared by
// the codec harness and make_corpus: a key at tick 1, then deltas, each cut into several chunks,
// plus the chunk <-> fuzz record encoding (21-byte envelope with 64-bit ticks, then the payload).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "byte_reader.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "synthetic_ocean.hpp"

namespace ocean::fuzz {

inline codec::StreamConfig codec_stream_config() {
  codec::StreamConfig c;
  c.grid = 16;
  c.rate_hz = 30;
  c.normals = true;
  return c;
}

inline constexpr std::size_t kCodecStreamPayload = 120;  // small, so frames span several chunks

inline codec::DecoderOptions codec_stream_decoder_options() {
  codec::DecoderOptions o;
  o.max_payload = kCodecStreamPayload;
  return o;
}

// The scene both sides know from tick 0 (tag 0). The synthetic ocean is not this scene, so keys
// carry explicit coefficients, as in tests/codec.
inline model::SceneParams codec_stream_scene() {
  const codec::StreamConfig c = codec_stream_config();
  model::SceneParams s;
  s.patch_x_m = c.patch_x_m;
  s.patch_z_m = c.patch_z_m;
  s.depth_m = model::scene_depth(c.depth_m);  // the config's 0 is deep water
  s.gravity_mps2 = c.gravity_mps2;
  s.size_x = s.size_z = std::max<int>(256, c.grid);
  return s;
}

inline codec::Decoder codec_stream_decoder() {
  codec::Decoder d(codec_stream_config(), codec_stream_decoder_options());
  d.add_scene(0, 0, codec_stream_scene());
  return d;
}

// frames[i] is tick i + 1: frames[0] the key, frames[i] a delta from tick i.
inline std::vector<std::shared_ptr<const codec::EncodedFrame>> make_codec_stream(int frame_count) {
  const codec::StreamConfig config = codec_stream_config();
  codec::EncoderOptions options;
  options.max_payload = kCodecStreamPayload;
  codec::Encoder encoder(config, options);
  encoder.set_scene(0, 0, codec_stream_scene());
  const codec::test::SyntheticOcean ocean(config.grid, config.patch_x_m, 40, 11, 0.5);
  std::vector<std::shared_ptr<const codec::EncodedFrame>> frames;
  for (Tick tick = 0; tick <= static_cast<Tick>(frame_count); ++tick) {
    const codec::test::SyntheticFrame f = ocean.at(tick * config.dt_s());
    encoder.add_truth(tick, codec::TruthView{f.height, f.slope_x, f.slope_z});
    if (tick == 1) frames.push_back(encoder.encode_key(1));
    if (tick > 1) frames.push_back(encoder.encode_delta(tick, frames.back()->id));
  }
  return frames;
}

inline constexpr std::size_t kEnvelopeRecordBytes = 21;

inline std::vector<std::uint8_t> chunk_record(const codec::Chunk& c) {
  std::vector<std::uint8_t> out;
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(c.tick >> (8 * i)));
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(c.baseline >> (8 * i)));
  out.push_back(c.key ? 1 : 0);
  out.push_back(static_cast<std::uint8_t>(c.index));
  out.push_back(static_cast<std::uint8_t>(c.index >> 8));
  out.push_back(static_cast<std::uint8_t>(c.count));
  out.push_back(static_cast<std::uint8_t>(c.count >> 8));
  out.insert(out.end(), c.payload.begin(), c.payload.end());
  return out;
}

inline codec::ChunkView chunk_view_of(std::span<const std::uint8_t> record) {
  ByteReader in(record);
  codec::ChunkView v;
  v.tick = in.take<std::uint64_t>();
  v.baseline = in.take<std::uint64_t>();
  v.key = (in.take<std::uint8_t>() & 1) != 0;
  v.index = in.take<std::uint16_t>();
  v.count = in.take<std::uint16_t>();
  v.payload = in.take_bytes(record.size());
  return v;
}

}  // namespace ocean::fuzz
