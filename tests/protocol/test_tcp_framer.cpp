// TcpFramer: any split of the stream yields the same messages; bad size prefixes are refused
// before a body byte is taken, and the framer never holds more than its maximum.
#include <catch2/catch.hpp>

#include "message_builders.hpp"
#include "sample_messages.hpp"
#include "tcp_framer.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;
using Status = TcpFramer::Status;

namespace {

std::vector<Bytes> sample_stream_messages() {
  std::vector<Bytes> messages;
  for (const Sample& sample : all_samples()) messages.push_back(encode(sample.message));
  return messages;
}

Bytes concatenate(const std::vector<Bytes>& messages) {
  Bytes stream;
  for (const Bytes& m : messages) stream.insert(stream.end(), m.begin(), m.end());
  return stream;
}

// Feeds the reads in order; returns every message the framer produced; fails on bad.
std::vector<Bytes> frame_all(TcpFramer& framer, const std::vector<std::span<const std::uint8_t>>& reads) {
  std::vector<Bytes> out;
  for (std::span<const std::uint8_t> read : reads) {
    while (!read.empty()) {
      const TcpFramer::Result r = framer.feed(read);
      REQUIRE(r.status != Status::bad);
      REQUIRE(r.consumed > 0);
      read = read.subspan(r.consumed);
      if (r.status == Status::good) {
        const auto message = framer.message();
        REQUIRE(reinterpret_cast<std::uintptr_t>(message.data()) % 8 == 0);
        out.emplace_back(message.begin(), message.end());
      }
    }
  }
  return out;
}

Bytes prefix(std::uint32_t size) {
  return Bytes{static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8),
               static_cast<std::uint8_t>(size >> 16), static_cast<std::uint8_t>(size >> 24)};
}

}  // namespace

TEST_CASE("framer: several messages in one read") {
  const std::vector<Bytes> messages = sample_stream_messages();
  const Bytes stream = concatenate(messages);
  TcpFramer framer;
  CHECK(frame_all(framer, {stream}) == messages);
  CHECK(framer.buffered_bytes() == 0);
}

TEST_CASE("framer: a stream split at every byte boundary gives the same messages") {
  const std::vector<Bytes> messages = sample_stream_messages();
  const Bytes stream = concatenate(messages);
  const std::span<const std::uint8_t> all(stream);
  for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
    TcpFramer framer;
    const auto got = frame_all(framer, {all.first(cut), all.subspan(cut)});
    INFO("cut at byte " << cut);
    REQUIRE(got == messages);
  }
}

TEST_CASE("framer: one byte per read") {
  const std::vector<Bytes> messages = sample_stream_messages();
  const Bytes stream = concatenate(messages);
  std::vector<std::span<const std::uint8_t>> reads;
  for (std::size_t i = 0; i < stream.size(); ++i) reads.emplace_back(&stream[i], 1);
  TcpFramer framer;
  CHECK(frame_all(framer, reads) == messages);
}

TEST_CASE("framer: messages from the framer pass verification") {
  TcpFramer framer;
  const Bytes frames = encode(sample_frame_data());
  REQUIRE(framer.feed(frames).status == Status::good);
  CHECK(verify_message(framer.message(), from_server()).ok);
}

TEST_CASE("framer: a size prefix over the maximum is refused before any body byte") {
  const std::size_t max = 2048;
  TcpFramer framer(max);
  Bytes stream = prefix(static_cast<std::uint32_t>(max - 4 + 1));
  stream.resize(stream.size() + 5000, 0xAB);  // the body that must not be taken

  const TcpFramer::Result r = framer.feed(stream);
  CHECK(r.status == Status::bad);
  CHECK(r.reason == Reason::oversized);
  CHECK(r.consumed == 4);
  CHECK(framer.buffered_bytes() <= 4);

  // Bad is sticky: nothing more is taken until reset.
  const TcpFramer::Result again = framer.feed(std::span<const std::uint8_t>(stream).subspan(4));
  CHECK(again.status == Status::bad);
  CHECK(again.consumed == 0);
  CHECK(framer.buffered_bytes() <= 4);

  framer.reset();
  const Bytes good = encode(sample_frame_data());
  CHECK(framer.feed(good).status == Status::good);
}

TEST_CASE("framer: a prefix exactly at the maximum is accepted") {
  const Bytes message = encode(sample_frame_data());
  TcpFramer framer(message.size());
  CHECK(framer.feed(message).status == Status::good);
  TcpFramer smaller(message.size() - 1);
  const auto r = smaller.feed(message);
  CHECK(r.status == Status::bad);
  CHECK(r.reason == Reason::oversized);
}

TEST_CASE("framer: a huge prefix split across reads is refused once the prefix is complete") {
  TcpFramer framer;
  const Bytes huge = prefix(0xFFFFFFFFu);
  CHECK(framer.feed(std::span<const std::uint8_t>(huge).first(3)).status == Status::need_more);
  const auto r = framer.feed(std::span<const std::uint8_t>(huge).subspan(3));
  CHECK(r.status == Status::bad);
  CHECK(r.reason == Reason::oversized);
  CHECK(r.consumed == 1);
}

TEST_CASE("framer: zero length and too-short prefixes are bad") {
  TcpFramer zero;
  const auto r0 = zero.feed(prefix(0));
  CHECK(r0.status == Status::bad);
  CHECK(r0.reason == Reason::empty);

  TcpFramer short_one;
  const auto r1 = short_one.feed(prefix(7));
  CHECK(r1.status == Status::bad);
  CHECK(r1.reason == Reason::truncated);

  TcpFramer nothing;
  const auto r2 = nothing.feed({});
  CHECK(r2.status == Status::need_more);
  CHECK(r2.consumed == 0);
}

TEST_CASE("framer: a lowered maximum applies to the next message") {
  const Bytes payload(3000, 1);
  const FrameRecord key{5, 5, true, 0, 1, payload};
  const Bytes big = encode(FrameData{encode_frame_block(std::span(&key, 1))});
  TcpFramer framer;
  CHECK(framer.feed(big).status == Status::good);
  framer.set_max_message_bytes(kMaxDatagram);
  CHECK(framer.max_message_bytes() == kMaxDatagram);
  const auto r = framer.feed(big);
  CHECK(r.status == Status::bad);
  CHECK(r.reason == Reason::oversized);
}
