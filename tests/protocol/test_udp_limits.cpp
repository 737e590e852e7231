// UDP: every datagram the builders make for UDP fits kMaxDatagram, one byte more is refused on
// receive, and the server's answer to an unproven datagram is never larger than it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "sample_messages.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;

namespace {

const VerifyOptions kFromServerUdp = from(Sender::server, wire::Transport::udp);

FrameChunk widest_chunk(std::size_t payload_bytes) {
  const std::uint32_t max_tick = std::numeric_limits<std::uint32_t>::max();
  return FrameChunk{FrameHeader{max_tick, max_tick - kMaxBaselineGap, false, 255},
                    kMaxChunksPerFrame - 1, kMaxChunksPerFrame, Bytes(payload_bytes, 0xEE)};
}

}  // namespace

TEST_CASE("a chunk with the largest UDP payload and widest fields fits one datagram") {
  FrameChunk chunk = widest_chunk(kMaxChunkPayloadUdp);
  chunk.frame.profile_id = 3;
  const Bytes bytes = encode(chunk);
  CHECK(bytes.size() <= kMaxDatagram);
  CHECK(fits_datagram(bytes));
  CHECK(verify_message(bytes, kFromServerUdp).ok);
}

TEST_CASE("kChunkOverheadBytes bounds the FrameChunk overhead at every payload alignment") {
  std::size_t worst = 0;
  for (std::size_t payload = 0; payload <= kMaxChunkPayloadUdp; payload += (payload < 16 ? 1 : 97))
    worst = std::max(worst, encode(widest_chunk(payload)).size() - payload);
  for (std::size_t payload = kMaxChunkPayloadUdp - 3; payload <= kMaxChunkPayloadUdp; ++payload)
    worst = std::max(worst, encode(widest_chunk(payload)).size() - payload);
  CHECK(worst <= kChunkOverheadBytes);
  CHECK(worst + 16 >= kChunkOverheadBytes);  // a bound, but not a loose one
}

TEST_CASE("split_frame at the UDP payload size makes only datagrams that fit") {
  Bytes payload(10 * kMaxChunkPayloadUdp + 17, 0x5A);
  const auto chunks = split_frame(FrameHeader{100000, 99990, false, 2}, payload, kMaxChunkPayloadUdp);
  REQUIRE(chunks.size() == 11);
  for (const Bytes& chunk : chunks) {
    CHECK(fits_datagram(chunk));
    CHECK(verify_message(chunk, kFromServerUdp).ok);
  }
}

TEST_CASE("a datagram over 1200 bytes is refused on send and on receive") {
  // Grow the payload until the message is exactly one byte over the limit.
  std::size_t payload = kMaxChunkPayloadUdp;
  Bytes bytes = encode(widest_chunk(payload));
  while (bytes.size() <= kMaxDatagram) bytes = encode(widest_chunk(++payload));
  CHECK_FALSE(fits_datagram(bytes));
  const Verified v = verify_message(bytes, kFromServerUdp);
  CHECK(v.reason == Reason::oversized);
  VerifyOptions tcp = kFromServerUdp;
  tcp.transport = wire::Transport::tcp;
  CHECK(verify_message(bytes, tcp).reason == Reason::unknown_profile);  // TCP allows the size; profile 255 is wrong
}

TEST_CASE("no amplification: UdpHello is padded and UdpReady is smaller") {
  for (std::size_t cookie : {kMinCookieBytes, kMaxCookieBytes}) {
    const Bytes hello = encode(UdpHello{1, Bytes(cookie, 3)});
    CHECK(hello.size() >= kUdpHelloMinBytes);
    CHECK(hello.size() < kUdpHelloMinBytes + 16);
    CHECK(fits_datagram(hello));
    CHECK(verify_message(hello, from(Sender::client, wire::Transport::udp)).ok);
    CHECK(encode(UdpReady{std::numeric_limits<std::uint64_t>::max()}).size() <= hello.size());
  }
}

TEST_CASE("every message allowed on UDP fits a datagram with its largest fields") {
  const Bytes cookie(kMaxCookieBytes, 0xCC);
  const std::uint64_t big = std::numeric_limits<std::uint64_t>::max();
  const std::uint32_t tick = std::numeric_limits<std::uint32_t>::max();
  for (const Bytes& bytes : {encode(Ack{big, cookie, tick, tick}),
                             encode(KeyframeRequest{big, cookie, wire::KeyframeReason::incomplete_frame}),
                             encode(Ping{big, cookie, tick, big}), encode(Pong{tick, big, tick, -1}),
                             encode(UdpHello{big, cookie}), encode(UdpReady{big})})
    CHECK(fits_datagram(bytes));
}

TEST_CASE("a FrameBundle re-encodes whole chunk messages exactly and is checked chunk by chunk") {
  FrameChunk a = sample_chunk(), b = sample_chunk();
  a.frame = FrameHeader{999, 998, false, 1};
  b.frame = FrameHeader{1000, 998, false, 1};
  const Bytes ma = encode(a), mb = encode(b);
  const std::vector<std::span<const std::uint8_t>> parts{ma, mb};
  const Bytes bundle = encode_bundle(parts);
  CHECK(bundle == encode(FrameBundle{{a, b}}));
  const Verified ok = verify_message(bundle, kFromServerUdp);
  REQUIRE(ok.ok);
  CHECK(std::get<FrameBundle>(decode(*ok.message)).chunks == std::vector<FrameChunk>{a, b});
  // UDP only, from the server only, 1..8 chunks, each a valid FrameChunk.
  CHECK(verify_message(bundle, from(Sender::server, wire::Transport::tcp)).reason == Reason::unexpected_message);
  CHECK(verify_message(bundle, from(Sender::client, wire::Transport::udp)).reason == Reason::unexpected_message);
  CHECK(verify_message(encode(FrameBundle{}), kFromServerUdp).reason == Reason::out_of_range);
  CHECK(verify_message(encode(FrameBundle{std::vector<FrameChunk>(kMaxBundleChunks + 1, a)}), kFromServerUdp).reason ==
        Reason::out_of_range);
  FrameChunk bad = b;
  bad.index = bad.count;
  const Verified refused = verify_message(encode(FrameBundle{{a, bad}}), kFromServerUdp);
  CHECK(refused.reason == Reason::bad_chunk_index);
  CHECK(refused.field == "FrameChunk.index");
}
