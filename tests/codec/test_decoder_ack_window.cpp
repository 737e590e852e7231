// Decoder::ack_window, kept as frames complete and age out, must be the window of exactly the
// ticks complete_ticks() lists: a client acks from it, and acking a tick it does not hold would
// have the server predict from a state the client cannot use.
#include "stream_harness.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <random>

using namespace ocean::codec;
using namespace ocean::codec::test;
using ocean::Tick;

TEST_CASE("the ack window names exactly the complete ticks through loss, reordering and eviction") {
  const StreamConfig config = test_config(32, 30);
  const SyntheticOcean ocean(32, 128.0, 120, 3, 0.4);
  const double dt = 1.0 / config.rate_hz;
  Encoder enc = test_encoder(config);
  DecoderOptions options;
  options.history_ticks = 20;  // evicts within the run
  Decoder dec = test_decoder(config, options);
  CHECK(!dec.ack_window());
  std::mt19937 rng(5);
  std::map<Tick, std::shared_ptr<const EncodedFrame>> held;  // sent, not yet delivered
  enc.add_truth(0, view_of(ocean.at(0.0)));
  enc.add_truth(1, view_of(ocean.at(dt)));
  const auto key = enc.encode_key(1);
  for (const Chunk& c : key->chunks) REQUIRE(dec.accept(c) == ChunkError::ok);
  StateId base = key->id;
  int checked = 0, dropped = 0, late = 0;
  for (Tick tick = 2; tick <= 150; ++tick) {
    enc.add_truth(tick, view_of(ocean.at(tick * dt)));
    const auto frame = enc.encode_delta(tick, base);
    const unsigned roll = rng() % 10;
    if (roll == 0) {
      ++dropped;  // lost
    } else if (roll == 1) {
      held[tick] = frame;  // delivered a few ticks late
    } else {
      for (const Chunk& c : frame->chunks) (void)dec.accept(c);
    }
    if (!held.empty() && (rng() % 3 == 0 || held.begin()->first + 5 < tick)) {
      for (const Chunk& c : held.begin()->second->chunks) (void)dec.accept(c);
      held.erase(held.begin());
      ++late;
    }
    if (dec.is_complete(tick) && tick % 4 == 0) base = frame->id;  // the client acked it
    const std::vector<Tick> ticks = dec.complete_ticks();
    REQUIRE(dec.ack_window());
    INFO("tick " << tick);
    REQUIRE(*dec.ack_window() == *ocean::protocol::ack_window(dec.complete_ticks()));
    ++checked;
  }
  CHECK(checked == 149);
  CHECK(dropped > 5);
  CHECK(late > 5);
  CHECK(dec.complete_ticks().size() < 25);  // eviction ran
}
