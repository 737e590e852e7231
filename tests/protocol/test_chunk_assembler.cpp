// ChunkAssembler: frames complete from chunks in any order, duplicates are harmless, the ack
// state follows the reliable/yojimbo convention, and every rejection leaves it unchanged.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "message_builders.hpp"
#include "receiver.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;

namespace {

Bytes payload_for(std::uint32_t tick, std::size_t size) {
  Bytes payload(size);
  for (std::size_t i = 0; i < size; ++i) payload[i] = static_cast<std::uint8_t>(tick * 31 + i);
  return payload;
}

std::vector<Bytes> frame_chunks(std::uint32_t tick, std::uint32_t baseline, std::size_t size = 100,
                                std::size_t max_payload = 30) {
  return split_frame(FrameHeader{tick, baseline, tick == baseline, 1}, payload_for(tick, size), max_payload);
}

const wire::FrameChunk& chunk_of(const Bytes& bytes) {
  const Verified v = verify_message(bytes, from_server());
  REQUIRE(v.ok);
  return *v.message->body_as_FrameChunk();
}

ChunkAssembler::Outcome add(ChunkAssembler& assembler, const Bytes& bytes) {
  return assembler.add(chunk_of(bytes));
}

void complete(ChunkAssembler& assembler, std::uint32_t tick) {
  const auto chunks = frame_chunks(tick, tick);
  for (const Bytes& c : chunks) REQUIRE(add(assembler, c).reason == Reason::ok);
  REQUIRE(assembler.completed(tick));
}

}  // namespace

TEST_CASE("assembler: chunks in shuffled order with duplicates give the frame once") {
  std::mt19937 rng(3);
  for (int round = 0; round < 20; ++round) {
    auto chunks = frame_chunks(500, 480, 1000, 64);
    chunks.push_back(chunks[3]);
    chunks.push_back(chunks[0]);
    std::shuffle(chunks.begin(), chunks.end(), rng);
    ChunkAssembler assembler;
    int frames = 0;
    Bytes payload;
    for (const Bytes& c : chunks) {
      auto outcome = add(assembler, c);
      if (outcome.reason == Reason::stale_tick) continue;  // a duplicate after completion
      REQUIRE(outcome.reason == Reason::ok);
      if (outcome.duplicate) CHECK_FALSE(outcome.frame);
      if (outcome.frame) {
        ++frames;
        CHECK(outcome.frame->header == FrameHeader{500, 480, false, 1});
        payload = outcome.frame->joined();
        CHECK(outcome.frame->chunks.size() == 16);
      }
    }
    CHECK(frames == 1);
    CHECK(payload == payload_for(500, 1000));
    CHECK(assembler.frames_in_flight() == 0);
    CHECK(assembler.ack_window() == AckWindow{500, 0});
  }
}

TEST_CASE("assembler: ack state is the latest tick plus a bit per earlier tick") {
  ChunkAssembler assembler;
  CHECK_FALSE(assembler.ack_window());
  complete(assembler, 10);
  CHECK(assembler.ack_window() == AckWindow{10, 0});
  complete(assembler, 12);  // 11 missing
  CHECK(assembler.ack_window() == AckWindow{12, 0b10u});  // bit 1 = tick 10
  complete(assembler, 11);  // arrives late
  CHECK(assembler.ack_window() == AckWindow{12, 0b11u});
  complete(assembler, 44);  // 32 ticks after 12: tick 12 is bit 31
  CHECK(assembler.ack_window() == AckWindow{44, 1u << 31});
  CHECK(assembler.completed(12));
  CHECK_FALSE(assembler.completed(11));
  complete(assembler, 100);  // far ahead: the field empties
  CHECK(assembler.ack_window() == AckWindow{100, 0});
  CHECK_FALSE(assembler.completed(44));
}

TEST_CASE("ack_window of a tick set does not depend on order and matches contains()") {
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::uint32_t> tick(1000, 1080);
  for (int round = 0; round < 200; ++round) {
    std::vector<std::uint32_t> ticks(1 + round % 20);
    for (auto& t : ticks) t = tick(rng);
    const auto window = ack_window(ticks);
    REQUIRE(window);
    const std::uint32_t newest = *std::max_element(ticks.begin(), ticks.end());
    CHECK(window->latest_tick == newest);
    for (std::uint32_t t = 990; t <= 1090; ++t) {
      const bool in_set = std::find(ticks.begin(), ticks.end(), t) != ticks.end();
      CHECK(window->contains(t) == (in_set && t <= newest && newest - t <= kAckWindowTicks));
    }
    std::shuffle(ticks.begin(), ticks.end(), rng);
    CHECK(ack_window(ticks) == window);
  }
  CHECK_FALSE(ack_window({}));
}

TEST_CASE("assembler: rejections name their reason and change nothing") {
  ChunkAssembler assembler;
  complete(assembler, 100);
  const auto partial = frame_chunks(101, 100);
  REQUIRE(add(assembler, partial[0]).reason == Reason::ok);
  const ChunkAssembler before = assembler;

  CHECK(add(assembler, frame_chunks(100, 100)[1]).reason == Reason::stale_tick);  // already complete
  CHECK(add(assembler, frame_chunks(60, 60)[0]).reason == Reason::stale_tick);    // beyond the ack window
  CHECK(add(assembler, frame_chunks(101, 99)[1]).reason == Reason::bad_sequence);  // other baseline
  CHECK(add(assembler, frame_chunks(101, 100, 100, 10)[1]).reason == Reason::bad_chunk_index);  // other count
  CHECK(assembler == before);

  ChunkAssembler::Limits tight;
  tight.max_frame_bytes = 70;  // the third 30-byte chunk goes over
  ChunkAssembler small(tight);
  const auto big = frame_chunks(7, 7, 100, 30);
  REQUIRE(add(small, big[0]).reason == Reason::ok);
  REQUIRE(add(small, big[1]).reason == Reason::ok);
  const ChunkAssembler small_before = small;
  CHECK(add(small, big[2]).reason == Reason::oversized);
  CHECK(small == small_before);
}

TEST_CASE("assembler: the oldest incomplete frame makes room, an older one is refused") {
  ChunkAssembler::Limits limits;
  limits.max_frames_in_flight = 2;
  ChunkAssembler assembler(limits);
  REQUIRE(add(assembler, frame_chunks(20, 20)[0]).reason == Reason::ok);
  REQUIRE(add(assembler, frame_chunks(21, 21)[0]).reason == Reason::ok);
  const ChunkAssembler before = assembler;
  CHECK(add(assembler, frame_chunks(19, 19)[0]).reason == Reason::stale_tick);
  CHECK(assembler == before);
  REQUIRE(add(assembler, frame_chunks(22, 22)[0]).reason == Reason::ok);  // drops 20
  CHECK(assembler.frames_in_flight() == 2);
  for (const Bytes& c : frame_chunks(21, 21)) add(assembler, c);
  CHECK(assembler.completed(21));
  CHECK(assembler.frames_in_flight() == 1);
}

TEST_CASE("receiver: a stream with losses delivers every complete frame") {
  std::mt19937 rng(11);
  std::bernoulli_distribution lost(0.05);
  Receiver receiver;
  std::size_t complete_frames = 0;
  for (std::uint32_t tick = 1; tick <= 200; ++tick) {
    bool all = true;
    for (const Bytes& c : frame_chunks(tick, tick == 1 ? 1 : tick - 1, 600, kMaxChunkPayloadUdp / 4)) {
      if (lost(rng)) {
        all = false;
        continue;
      }
      REQUIRE(receiver.receive(c, from(Sender::server, wire::Transport::udp)) == Reason::ok);
    }
    complete_frames += all;
    CHECK(receiver.assembler.completed(tick) == all);
  }
  CHECK(receiver.frames == complete_frames);
  CHECK(receiver.assembler.frames_in_flight() <= ChunkAssembler::Limits{}.max_frames_in_flight);
}
