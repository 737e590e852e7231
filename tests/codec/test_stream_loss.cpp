// Loss: a lost chunk costs only its rows of that frame; a lost frame costs nothing once the next
// frame is predicted from an acknowledged baseline; recovery is exact (bitwise).
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

using namespace ocean::codec;
using namespace ocean::codec::test;

namespace {

EncoderOptions coarse_options() {
  EncoderOptions o;
  o.key_precision_bits = 0;  // forces corrections so frames span several chunks
  o.key_velocity_extra_bits = 0;
  o.max_payload = 400;
  return o;
}

}  // namespace

TEST_CASE("random chunk loss: every completed frame matches the encoder exactly, within the bound") {
  const StreamConfig c = test_config(32, 15);
  const SyntheticOcean ocean(32, 256.0, 150, 21, 0.5);
  for (double loss : {0.05, 0.2}) {
    for (std::uint32_t lag : {1u, 4u}) {
      const RunStats st = run_stream(ocean, c, coarse_options(), 400, lag, LinkModel{loss, 99});
      INFO("loss " << loss << " lag " << lag << " complete " << st.complete_frames << " chunks " << st.delta_chunks);
      CHECK(st.rejected == 0);
      CHECK(st.bitwise);
      CHECK(st.states_equal);
      CHECK(st.complete_frames > 50);
      CHECK(st.complete_frames < st.frames);  // loss really happened
      CHECK(st.max_height_err <= 0.5 * double(c.height_step_m));
      CHECK(st.max_slope_err <= 0.5 * double(c.slope_step));
    }
  }
}

TEST_CASE("a lost frame and a partly lost frame: the next frame from the acked baseline is exact") {
  const StreamConfig c = test_config(32, 30);
  const SyntheticOcean ocean(32, 256.0, 150, 4, 0.5);
  Encoder enc = test_encoder(c, coarse_options());
  DecoderOptions dopt;
  dopt.max_payload = 400;
  Decoder dec = test_decoder(c, dopt);
  const double dt = 1.0 / 30;
  for (std::uint32_t t = 0; t <= 13; ++t) enc.add_truth(t, view_of(ocean.at(t * dt)));
  auto key = enc.encode_key(1);
  for (const Chunk& ch : key->chunks) REQUIRE(dec.accept(ch) == ChunkError::ok);
  REQUIRE(dec.is_complete(1));
  StateId acked = key->id;
  for (std::uint32_t t = 2; t <= 9; ++t) {  // normal frames, each acked
    auto f = enc.encode_delta(t, acked);
    for (const Chunk& ch : f->chunks) REQUIRE(dec.accept(ch) == ChunkError::ok);
    REQUIRE(dec.is_complete(t));
    acked = f->id;
  }
  // Tick 10 lost entirely; tick 11 loses its first chunk; both predicted from acked tick 9.
  auto f10 = enc.encode_delta(10, acked);
  auto f11 = enc.encode_delta(11, acked);
  REQUIRE(f11->chunks.size() > 1);
  for (std::size_t i = 1; i < f11->chunks.size(); ++i) REQUIRE(dec.accept(f11->chunks[i]) == ChunkError::ok);
  CHECK_FALSE(dec.is_complete(10));
  CHECK_FALSE(dec.is_complete(11));
  const ReconstructedFrame* partial = dec.latest();
  REQUIRE(partial);
  CHECK(partial->tick == 11);
  CHECK_FALSE(partial->complete);
  // Rows of the received chunks are already exact; the missing rows show the prediction.
  CHECK(partial->height != f11->reconstruction.height);
  // Tick 12 predicted from the last acked tick 9: complete and bit-exact, as is its state.
  auto f12 = enc.encode_delta(12, acked);
  for (const Chunk& ch : f12->chunks) REQUIRE(dec.accept(ch) == ChunkError::ok);
  REQUIRE(dec.is_complete(12));
  const ReconstructedFrame* r = dec.latest();
  REQUIRE(r);
  CHECK(r->tick == 12);
  CHECK(r->complete);
  CHECK(r->height == f12->reconstruction.height);
  CHECK(r->slope_x == f12->reconstruction.slope_x);
  CHECK(r->slope_z == f12->reconstruction.slope_z);
  CHECK(*dec.state(12) == *enc.state(f12->id));
  // The late first chunk of 11 still completes 11, exactly; 11 can then serve as a baseline.
  REQUIRE(dec.accept(f11->chunks[0]) == ChunkError::ok);
  CHECK(dec.is_complete(11));
  CHECK(*dec.state(11) == *enc.state(f11->id));
  auto f13 = enc.encode_delta(13, f11->id);
  for (const Chunk& ch : f13->chunks) REQUIRE(dec.accept(ch) == ChunkError::ok);
  CHECK(dec.latest()->height == f13->reconstruction.height);
}
