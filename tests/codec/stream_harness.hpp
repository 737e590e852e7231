// Test harness: drives an Encoder and a Decoder over a SyntheticOcean through a perfect or lossy
// link, with the server's baseline policy (newest acknowledged state at least `lag` ticks back).
#pragma once

#include "decoder.hpp"
#include "encoder.hpp"
#include "synthetic_ocean.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <random>

namespace ocean::codec::test {

inline StreamConfig test_config(int n, int rate_hz = 30, bool normals = true) {
  StreamConfig c;
  c.grid = static_cast<std::uint16_t>(n);
  c.rate_hz = static_cast<std::uint16_t>(rate_hz);
  c.normals = normals;
  return c;
}

inline TruthView view_of(const SyntheticFrame& f) { return {f.height, f.slope_x, f.slope_z}; }

// The scene both sides are told of. The synthetic ocean is not this scene, so its keys fall back
// to explicit coefficients; test_scene_model.cpp covers modeled keys against the real sim.
inline model::SceneParams test_scene(const StreamConfig& c) {
  model::SceneParams s;
  s.patch_x_m = c.patch_x_m;
  s.patch_z_m = c.patch_z_m;
  s.depth_m = model::scene_depth(c.depth_m);
  s.gravity_mps2 = c.gravity_mps2;
  s.size_x = s.size_z = std::max<int>(256, c.grid);
  return s;
}

// An encoder and a decoder of one stream that both know its scene from tick 0.
inline Encoder test_encoder(const StreamConfig& c, const EncoderOptions& options = {}) {
  Encoder e(c, options);
  e.set_scene(0, 0, test_scene(c));
  return e;
}
inline Decoder test_decoder(const StreamConfig& c, const DecoderOptions& options = {}) {
  Decoder d(c, options);
  d.add_scene(0, 0, test_scene(c));
  return d;
}

struct RunStats {
  int frames = 0;
  int complete_frames = 0;
  double max_height_err = 0.0;   // over complete frames, metres
  double max_slope_err = 0.0;
  bool bitwise = true;           // every complete decoder frame equals the encoder's reconstruction
  bool states_equal = true;      // and its state equals the encoder's
  std::size_t delta_bytes = 0, delta_chunks = 0, key_bytes = 0;
  std::size_t corrections = 0;
  int rejected = 0;
};

struct LinkModel {
  double chunk_loss = 0.0;  // probability a chunk is dropped
  std::uint64_t seed = 7;
};

// Streams `frames` ticks starting at tick 1 (the key), acks arriving `lag` ticks late.
inline RunStats run_stream(const SyntheticOcean& ocean, const StreamConfig& config, const EncoderOptions& eopt,
                           int frames, std::uint32_t lag, LinkModel link = {}) {
  Encoder enc = test_encoder(config, eopt);
  DecoderOptions dopt;
  dopt.max_payload = eopt.max_payload;
  Decoder dec = test_decoder(config, dopt);
  RunStats st;
  std::mt19937_64 rng(link.seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double dt = 1.0 / config.rate_hz;
  std::map<Tick, StateId> sent;  // tick -> version sent to this client
  std::map<Tick, std::shared_ptr<const EncodedFrame>> encoded;
  std::optional<Tick> acked;  // newest tick the server knows complete
  enc.add_truth(0, view_of(ocean.at(0.0)));
  for (int i = 0; i < frames; ++i) {
    const Tick tick = 1 + static_cast<Tick>(i);
    const SyntheticFrame truth = ocean.at(tick * dt);
    enc.add_truth(tick, view_of(truth));
    // Acks of frames completed at least `lag` ticks ago have reached the server.
    for (Tick t : dec.complete_ticks())
      if (t + lag <= tick && (!acked || t > *acked) && sent.count(t)) acked = t;
    std::shared_ptr<const EncodedFrame> f;
    if (!acked || !enc.has_state(sent[*acked]))
      f = enc.encode_key(tick);
    else
      f = enc.encode_delta(tick, sent[*acked]);
    sent[tick] = f->id;
    encoded[tick] = f;
    std::size_t bytes = 0;
    for (const Chunk& c : f->chunks) {
      bytes += c.payload.size();
      if (link.chunk_loss > 0 && u01(rng) < link.chunk_loss) continue;
      if (dec.accept(c) != ChunkError::ok) ++st.rejected;
    }
    if (f->key)
      st.key_bytes += bytes;
    else {
      st.delta_bytes += bytes;
      st.delta_chunks += f->chunks.size();
    }
    st.corrections += f->stats.corrections_height + f->stats.corrections_slope;
    ++st.frames;
    if (dec.is_complete(tick)) {
      ++st.complete_frames;
      const ReconstructedFrame* r = dec.latest();
      // Tick, baseline (a key's own tick) and fields as the encoder sent them.
      if (!r || r->tick != tick || r->baseline != (f->key ? tick : f->base.tick) ||
          r->height != f->reconstruction.height || r->slope_x != f->reconstruction.slope_x ||
          r->slope_z != f->reconstruction.slope_z)
        st.bitwise = false;
      if (!(*dec.state(tick) == *enc.state(f->id))) st.states_equal = false;
      if (r)
        for (std::size_t k = 0; k < truth.height.size(); ++k) {
          st.max_height_err = std::max(st.max_height_err, std::fabs(double(truth.height[k]) - double(r->height[k])));
          if (config.normals) {
            st.max_slope_err = std::max(st.max_slope_err, std::fabs(double(truth.slope_x[k]) - double(r->slope_x[k])));
            st.max_slope_err = std::max(st.max_slope_err, std::fabs(double(truth.slope_z[k]) - double(r->slope_z[k])));
          }
        }
    }
  }
  return st;
}

}  // namespace ocean::codec::test
