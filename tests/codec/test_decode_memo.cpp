// DecodeMemo: decoders that share a memo show exactly what a lone decoder shows, decode each
// distinct (baseline, bytes) once, and never serve a frame for different inputs.
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

using namespace ocean::codec;
using namespace ocean::codec::test;
namespace model = ocean::model;
using ocean::Tick;

namespace {

bool same_frame(const ReconstructedFrame* a, const ReconstructedFrame* b) {
  return a && b && a->tick == b->tick && a->baseline == b->baseline && a->complete == b->complete &&
         a->height == b->height && a->slope_x == b->slope_x && a->slope_z == b->slope_z;
}

// Payloads large enough that every delta is one chunk (the memo only shares single-chunk deltas).
constexpr std::size_t kWide = 16000;
EncoderOptions wide_encoder() {
  EncoderOptions o;
  o.max_payload = kWide;
  return o;
}
DecoderOptions wide_decoder(DecodeMemo* memo) {
  DecoderOptions o;
  o.max_payload = kWide;
  o.memo = memo;
  return o;
}

}  // namespace

TEST_CASE("decoders sharing a memo match a lone decoder bit for bit and share the work") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 5, 0.4);
  const double dt = 1.0 / config.rate_hz;
  Encoder enc = test_encoder(config, wide_encoder());
  DecodeMemo memo(config);
  Decoder lone = test_decoder(config, wide_decoder(nullptr));
  Decoder a = test_decoder(config, wide_decoder(&memo));
  Decoder b = test_decoder(config, wide_decoder(&memo));
  enc.add_truth(0, view_of(ocean.at(0.0)));
  std::map<std::uint32_t, StateId> sent;
  int compared = 0, other_baseline = 0;
  for (std::uint32_t tick = 1; tick <= 60; ++tick) {
    enc.add_truth(tick, view_of(ocean.at(tick * dt)));
    std::shared_ptr<const EncodedFrame> f =
        tick == 1 ? enc.encode_key(tick) : enc.encode_delta(tick, sent[tick - (tick > 3 ? 2 : 1)]);
    sent[tick] = f->id;
    for (const Chunk& c : f->chunks) {
      REQUIRE(lone.accept(c) == ChunkError::ok);
      REQUIRE(a.accept(c) == ChunkError::ok);
      REQUIRE(b.accept(c) == ChunkError::ok);
    }
    REQUIRE(same_frame(lone.latest(), a.latest()));
    REQUIRE(same_frame(lone.latest(), b.latest()));
    REQUIRE(*lone.state(tick) == *a.state(tick));
    REQUIRE(a.state(tick) == b.state(tick));  // one interned object
    if (!f->key) {
      REQUIRE(f->chunks.size() == 1);
      CHECK(a.latest()->shared_id != 0);
      CHECK(a.latest()->shared_id == b.latest()->shared_id);
      CHECK(lone.latest()->shared_id == 0);
    }
    ++compared;
    // The same tick from another baseline: other bytes, so the memo must not answer with the first.
    if (tick > 4 && tick % 5 == 0) {
      const auto other = enc.encode_delta(tick, sent[tick - 1]);
      REQUIRE(other->chunks.size() == 1);
      CHECK(other->chunks[0].payload != f->chunks[0].payload);
      ++other_baseline;
    }
  }
  CHECK(compared == 60);
  CHECK(other_baseline > 0);
  // b found every single-chunk delta that a decoded first.
  CHECK(memo.counts().hits >= 59);
  CHECK(memo.counts().misses >= 59);
}

TEST_CASE("a memo advances a shared baseline step by step, out of order and across a scene change, bit for bit") {
  // Sessions on an aligned baseline get deltas of many ticks from one state: the memo advances
  // that state from the newest tick it reached. The results must equal a lone decoder's.
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 5, 0.4);
  const double dt = 1.0 / config.rate_hz;
  constexpr Tick kSceneChange = 24;
  model::SceneParams storm = test_scene(config);
  storm.wind_speed_mps *= 1.5;
  Encoder enc = test_encoder(config, wide_encoder());
  enc.set_scene(kSceneChange, 1, storm);
  DecodeMemo memo(config);
  Decoder lone = test_decoder(config, wide_decoder(nullptr));
  Decoder a = test_decoder(config, wide_decoder(&memo));
  Decoder b = test_decoder(config, wide_decoder(&memo));
  for (Decoder* d : {&lone, &a, &b}) d->add_scene(kSceneChange, 1, storm);
  enc.add_truth(0, view_of(ocean.at(0.0)));
  enc.add_truth(1, view_of(ocean.at(dt)));
  const auto key = enc.encode_key(1);
  for (Decoder* d : {&lone, &a, &b})
    for (const Chunk& c : key->chunks) REQUIRE(d->accept(c) == ChunkError::ok);
  // Every delta from the key's state; b sees the ticks in another order than a.
  std::vector<Tick> order_a, order_b;
  for (Tick t = 2; t <= 30; ++t) order_a.push_back(t);
  order_b = order_a;
  std::reverse(order_b.begin() + 5, order_b.begin() + 15);
  std::map<Tick, std::shared_ptr<const EncodedFrame>> deltas;
  for (Tick t : order_a) {
    enc.add_truth(t, view_of(ocean.at(t * dt)));
    deltas[t] = enc.encode_delta(t, key->id);
    REQUIRE(deltas[t]->chunks.size() == 1);
  }
  for (std::size_t i = 0; i < order_a.size(); ++i) {
    REQUIRE(lone.accept(deltas[order_a[i]]->chunks[0]) == ChunkError::ok);
    REQUIRE(a.accept(deltas[order_a[i]]->chunks[0]) == ChunkError::ok);
    REQUIRE(b.accept(deltas[order_b[i]]->chunks[0]) == ChunkError::ok);
  }
  for (Tick t : order_a) {
    INFO("tick " << t);
    REQUIRE(a.state(t) != nullptr);
    REQUIRE(b.state(t) != nullptr);
    CHECK(*lone.state(t) == *a.state(t));
    CHECK(*lone.state(t) == *b.state(t));
  }
  CHECK(*enc.state(deltas[30]->id) == *a.state(30));
}

TEST_CASE("a key of several chunks is decoded once for every decoder of a memo") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 13, 0.4);
  EncoderOptions narrow;
  narrow.max_payload = 400;
  Encoder enc = test_encoder(config, narrow);
  enc.add_truth(0, view_of(ocean.at(0.0)));
  enc.add_truth(1, view_of(ocean.at(1.0 / config.rate_hz)));
  const auto key = enc.encode_key(1);
  REQUIRE(key->chunks.size() > 2);
  DecodeMemo memo(config);
  Decoder lone = test_decoder(config, wide_decoder(nullptr));
  Decoder a = test_decoder(config, wide_decoder(&memo));
  Decoder b = test_decoder(config, wide_decoder(&memo));
  for (Decoder* d : {&lone, &a})
    for (const Chunk& c : key->chunks) REQUIRE(d->accept(c) == ChunkError::ok);
  for (auto c = key->chunks.rbegin(); c != key->chunks.rend(); ++c) REQUIRE(b.accept(*c) == ChunkError::ok);  // any order
  CHECK(memo.counts().misses == 1);
  CHECK(memo.counts().hits == 1);
  CHECK(memo.counts().intern_hits == 0);  // b never decoded it
  CHECK(a.state(1) == b.state(1));
  CHECK(*a.state(1) == *lone.state(1));
  CHECK(same_frame(a.latest(), lone.latest()));
  CHECK(a.latest()->shared_id == b.latest()->shared_id);
}

TEST_CASE("a key of one chunk is taken from the memo before a decoder does any work") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 17, 0.4);
  Encoder enc = test_encoder(config, wide_encoder());
  enc.add_truth(0, view_of(ocean.at(0.0)));
  enc.add_truth(1, view_of(ocean.at(1.0 / config.rate_hz)));
  const auto key = enc.encode_key(1);
  REQUIRE(key->chunks.size() == 1);
  DecodeMemo memo(config);
  Decoder lone = test_decoder(config, wide_decoder(nullptr));
  std::vector<Decoder> shared;
  for (int i = 0; i < 3; ++i) shared.push_back(test_decoder(config, wide_decoder(&memo)));
  REQUIRE(lone.accept(key->chunks[0]) == ChunkError::ok);
  for (Decoder& d : shared) REQUIRE(d.accept(key->chunks[0]) == ChunkError::ok);
  CHECK(memo.counts().misses == 1);
  CHECK(memo.counts().hits == 2);
  CHECK(memo.counts().intern_hits == 0);
  for (Decoder& d : shared) {
    CHECK(d.state(1) == shared[0].state(1));
    CHECK(*d.state(1) == *lone.state(1));
    CHECK(same_frame(d.latest(), lone.latest()));
  }
  // Another tick's key with the same bytes is not the same key.
  enc.add_truth(2, view_of(ocean.at(2.0 / config.rate_hz)));
  const auto next = enc.encode_key(2);
  REQUIRE(next->chunks.size() == 1);
  for (Decoder& d : shared) REQUIRE(d.accept(next->chunks[0]) == ChunkError::ok);
  REQUIRE(lone.accept(next->chunks[0]) == ChunkError::ok);
  CHECK(*shared[2].state(2) == *lone.state(2));
  CHECK(memo.counts().misses == 2);
}

TEST_CASE("a memo answers only for the exact baseline object and bytes") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 9, 0.4);
  const double dt = 1.0 / config.rate_hz;
  Encoder enc = test_encoder(config, wide_encoder());
  DecodeMemo memo(config);
  enc.add_truth(0, view_of(ocean.at(0.0)));
  enc.add_truth(1, view_of(ocean.at(dt)));
  const auto key = enc.encode_key(1);
  enc.add_truth(2, view_of(ocean.at(2 * dt)));
  enc.add_truth(3, view_of(ocean.at(3 * dt)));
  const auto d2 = enc.encode_delta(2, key->id);
  const auto d3_from_key = enc.encode_delta(3, key->id);
  const auto d3_from_2 = enc.encode_delta(3, d2->id);
  Decoder lone = test_decoder(config, wide_decoder(nullptr));
  Decoder x = test_decoder(config, wide_decoder(&memo));
  Decoder y = test_decoder(config, wide_decoder(&memo));
  for (Decoder* d : {&lone, &x, &y})
    for (const Chunk& c : key->chunks) REQUIRE(d->accept(c) == ChunkError::ok);
  // x: 3 from the key; y: 2, then 3 from 2. Same tick, different inputs: different results.
  REQUIRE(x.accept(d3_from_key->chunks[0]) == ChunkError::ok);
  REQUIRE(y.accept(d2->chunks[0]) == ChunkError::ok);
  REQUIRE(y.accept(d3_from_2->chunks[0]) == ChunkError::ok);
  REQUIRE(lone.accept(d2->chunks[0]) == ChunkError::ok);
  REQUIRE(lone.accept(d3_from_2->chunks[0]) == ChunkError::ok);
  CHECK(memo.counts().hits == 1);  // y's key, from x's decode; no delta answered for other inputs
  CHECK(same_frame(lone.latest(), y.latest()));
  CHECK(x.latest()->shared_id != y.latest()->shared_id);
  CHECK(*x.state(3) == *enc.state(d3_from_key->id));
  CHECK(*y.state(3) == *enc.state(d3_from_2->id));
}

TEST_CASE("a memo of another stream configuration is refused") {
  DecodeMemo memo(test_config(32, 30));
  DecoderOptions shared;
  shared.memo = &memo;
  CHECK_THROWS_AS(Decoder(test_config(64, 30), shared), std::invalid_argument);
}

TEST_CASE("a frame that completes after a newer one is still handed out by just_completed") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 11, 0.4);
  const double dt = 1.0 / config.rate_hz;
  Encoder enc = test_encoder(config, wide_encoder());
  for (std::uint32_t t = 0; t <= 4; ++t) enc.add_truth(t, view_of(ocean.at(t * dt)));
  const auto key = enc.encode_key(1);
  const auto d3 = enc.encode_delta(3, key->id);
  const auto d4 = enc.encode_delta(4, key->id);
  DecodeMemo memo(config);
  for (DecodeMemo* m : {static_cast<DecodeMemo*>(nullptr), &memo}) {
    for (int round = 0; round < 2; ++round) {  // with a memo, the second round is answered by it
      Decoder d = test_decoder(config, wide_decoder(m));
      for (const Chunk& c : key->chunks) REQUIRE(d.accept(c) == ChunkError::ok);
      REQUIRE(d.accept(d4->chunks[0]) == ChunkError::ok);
      REQUIRE(d.just_completed() != nullptr);
      CHECK(d.just_completed()->tick == 4u);
      REQUIRE(d.accept(d3->chunks[0]) == ChunkError::ok);  // the late one
      const ReconstructedFrame* late = d.just_completed();
      REQUIRE(late != nullptr);
      CHECK(late->tick == 3u);
      CHECK(late->complete);
      CHECK(late->height == d3->reconstruction.height);
      CHECK(d.latest()->tick == 4u);  // the newest stays on show
      CHECK(d.latest()->height == d4->reconstruction.height);
      CHECK(d.accept(d3->chunks[0]) == ChunkError::duplicate_chunk);
      CHECK(d.just_completed() == nullptr);
    }
  }
  CHECK(memo.counts().hits >= 2);
}
