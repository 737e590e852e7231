// Determinism of the prediction path: independent decoders (and the encoder) reach identical
// states; chunk order within a frame does not matter; the recurrence tracks exact rotation.
#include "det_math.hpp"
#include "modal_model.hpp"
#include "state_hash.hpp"
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace ocean::codec;
using namespace ocean::codec::test;
namespace model = ocean::model;

TEST_CASE("two decoders and the encoder agree on the state hash after hundreds of frames") {
  const StreamConfig c = test_config(32, 30);
  const SyntheticOcean ocean(32, 256.0, 120, 8, 0.5);
  EncoderOptions o;
  o.key_precision_bits = 1;  // some corrections so the correction path is covered
  o.max_payload = 200;
  Encoder enc = test_encoder(c, o);
  DecoderOptions dopt;
  dopt.max_payload = 200;
  Decoder a = test_decoder(c, dopt);
  Decoder b = test_decoder(c, dopt);
  std::mt19937_64 rng(5);
  const double dt = 1.0 / 30;
  enc.add_truth(0, view_of(ocean.at(0)));
  enc.add_truth(1, view_of(ocean.at(dt)));
  auto f = enc.encode_key(1);
  std::map<std::uint32_t, StateId> ids{{1, f->id}};
  auto feed = [&](const EncodedFrame& fr) {
    for (const Chunk& ch : fr.chunks) REQUIRE(a.accept(ch) == ChunkError::ok);
    std::vector<Chunk> shuffled = fr.chunks;  // b gets each frame's chunks in another order
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    for (const Chunk& ch : shuffled) REQUIRE(b.accept(ch) == ChunkError::ok);
  };
  feed(*f);
  const std::uint32_t last = 400;
  for (std::uint32_t t = 2; t <= last; ++t) {
    enc.add_truth(t, view_of(ocean.at(t * dt)));
    f = enc.encode_delta(t, ids.at(t > 3 ? t - 3 : 1));
    ids[t] = f->id;
    feed(*f);
  }
  const std::uint64_t ha = hash_state(*a.state(last));
  CHECK(ha == hash_state(*b.state(last)));
  CHECK(ha == hash_state(*enc.state(ids.at(last))));
  CHECK(a.latest()->height == b.latest()->height);
}

TEST_CASE("coefficient tables do not depend on the instance") {
  StreamConfig c = test_config(64, 30);
  c.depth_m = 12.5;
  ModalModel m1(c), m2(c);
  for (int i = 0; i < m1.half_size(); ++i) REQUIRE(m1.recurrence_coef(i) == m2.recurrence_coef(i));
}

TEST_CASE("the fixed-point recurrence follows exact rotation of a mode for thousands of ticks") {
  // One mode X(t) = A cos(w t dt) (+ the same at -k): compare with double after 5000 ticks.
  const StreamConfig c = test_config(32, 30, false);
  ModalModel model(c);
  ModalState s = model.zero_state();
  const int hc = model.n() / 2 + 1;
  const int at = 3 * hc + 5;  // kz index 3, kx index 5
  const double kx = model::kTwoPi * 5 / c.patch_x_m, kz = model::kTwoPi * 3 / c.patch_z_m;
  const double w = std::sqrt(c.gravity_mps2 * std::hypot(kx, kz));
  const double theta = w / c.rate_hz;
  const double amp = std::ldexp(1.0, 40);
  s.prev.re[at] = static_cast<std::int64_t>(std::llround(amp * std::cos(-theta)));
  s.cur.re[at] = static_cast<std::int64_t>(std::llround(amp));
  double worst = 0;
  for (int t = 1; t <= 5000; ++t) {
    model.advance(s);
    worst = std::max(worst, std::fabs(double(s.cur.re[at]) - amp * std::cos(theta * (t + 0))) / amp);
  }
  // Initial rounding (2^-40 relative) amplified by 1/theta and the Q48 coefficient error.
  CHECK(worst < 1e-9);
}
