// UDP: every datagram the builders make for UDP fits kMaxDatagram, one byte more is refused on
// receive, and the server's answer to an unproven datagram is never larger than it. Version 2:
// server datagrams start with a kind byte - frame records (frames_datagram) or a message
// (message_datagram) - and kChunkOverheadBytes bounds what a record needs besides its payload in a
// frames datagram and in a FrameData message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "frame_blocks.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "receiver.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;

namespace {

const VerifyOptions kFromServerUdp = from(Sender::server, wire::Transport::udp);
using ocean::kLargestTick;

// The record with the widest envelope: the largest tick (a 10-byte varint), the largest lag, the
// last chunk of the most chunks a frame may have.
FrameRecord widest_record(std::span<const std::uint8_t> payload) {
  return FrameRecord{kLargestTick, kLargestTick - kMaxFrameLag, false, kMaxChunksPerFrame - 1, kMaxChunksPerFrame,
                     payload};
}

Bytes widest_datagram(const Bytes& payload) {
  const FrameRecord r = widest_record(payload);
  return frames_datagram(std::span(&r, 1));
}

Bytes widest_frame_data(const Bytes& payload) {
  const FrameRecord r = widest_record(payload);
  return encode(FrameData{encode_frame_block(std::span(&r, 1))});
}

}  // namespace

TEST_CASE("a record with the largest UDP payload and widest fields fits one datagram") {
  const Bytes payload(kMaxChunkPayloadUdp, 0xEE);
  const Bytes datagram = widest_datagram(payload);
  CHECK(datagram.size() <= kMaxDatagram);
  CHECK(fits_datagram(datagram));
  CHECK(datagram[0] == static_cast<std::uint8_t>(DatagramKind::frames));
  std::vector<FrameRecord> records;
  const FrameBlockResult parsed = decode_frame_block(std::span(datagram).subspan(1), records);
  INFO(parsed.rule);
  REQUIRE(parsed);
  REQUIRE(records.size() == 1);
  CHECK(same_record(records[0], widest_record(payload)));
  Receiver receiver;
  CHECK(receiver.receive_datagram(datagram) == Reason::ok);
  CHECK(receiver.seen == std::vector<std::pair<ocean::Tick, std::uint16_t>>{{kLargestTick, kMaxChunksPerFrame - 1}});
}

TEST_CASE("kChunkOverheadBytes bounds the record overhead at every payload alignment") {
  std::size_t worst_datagram = 0, worst_message = 0;
  auto measure = [&](std::size_t n) {
    const Bytes payload(n, 0xEE);
    worst_datagram = std::max(worst_datagram, widest_datagram(payload).size() - n);
    worst_message = std::max(worst_message, widest_frame_data(payload).size() - n);
  };
  for (std::size_t payload = 0; payload <= kMaxChunkPayloadUdp; payload += (payload < 16 ? 1 : 97)) measure(payload);
  for (std::size_t payload = kMaxChunkPayloadUdp - 8; payload <= kMaxChunkPayloadUdp; ++payload) measure(payload);
  // Lengths whose varint grows (127/128, 16383/16384) and a large TCP payload.
  for (std::size_t payload : {127, 128, 129, 16383, 16384, 16385, 70000}) measure(payload);
  INFO("frames datagram: " << worst_datagram << ", FrameData message: " << worst_message);
  CHECK(worst_datagram <= 1 + 10 + kMaxRecordOverheadBytes);  // kind, newest tick, one record header
  CHECK(worst_datagram <= kChunkOverheadBytes);
  CHECK(worst_message <= kChunkOverheadBytes);
  // A bound, but not a loose one. (Measured with FlatBuffers 2.x: 79 for FrameData, 21 for a frames
  // datagram; version 1's FrameChunk needed 87, hence 96.)
  CHECK(worst_message + 24 >= kChunkOverheadBytes);
}

TEST_CASE("a FrameData with the largest TCP payload fits the session's message limit") {
  for (std::size_t limit : {kMinMaxMessageBytes, kDefaultMaxMessageBytes, kMaxMaxMessageBytes}) {
    INFO("max_message_bytes " << limit);
    const Bytes bytes = widest_frame_data(Bytes(max_chunk_payload(limit), 0x11));
    CHECK(bytes.size() <= limit);
    VerifyOptions options = from_server();
    options.max_message_bytes = limit;
    CHECK(verify_message(bytes, options).ok);
  }
}

TEST_CASE("a frame cut at the UDP payload size makes frames datagrams that all fit") {
  const Bytes payload(10 * kMaxChunkPayloadUdp + 17, 0x5A);
  const std::size_t count = (payload.size() + kMaxChunkPayloadUdp - 1) / kMaxChunkPayloadUdp;
  REQUIRE(count == 11);
  Receiver receiver;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t begin = i * kMaxChunkPayloadUdp;
    const FrameRecord chunk{100000, 99990, false, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(count),
                            std::span(payload).subspan(begin, std::min(kMaxChunkPayloadUdp, payload.size() - begin))};
    const Bytes datagram = frames_datagram(std::span(&chunk, 1));
    CHECK(fits_datagram(datagram));
    CHECK(receiver.receive_datagram(datagram) == Reason::ok);
  }
  REQUIRE(receiver.seen.size() == count);
  for (std::size_t i = 0; i < count; ++i) CHECK(receiver.seen[i] == std::pair<ocean::Tick, std::uint16_t>{100000, static_cast<std::uint16_t>(i)});
}

TEST_CASE("a datagram over 1200 bytes is refused on send and on receive") {
  // Grow the payload until the datagram is exactly one byte over the limit.
  Bytes payload(kMaxChunkPayloadUdp, 0xEE);
  Bytes datagram = widest_datagram(payload);
  while (datagram.size() <= kMaxDatagram) {
    payload.push_back(0xEE);
    datagram = widest_datagram(payload);
  }
  CHECK(datagram.size() == kMaxDatagram + 1);
  CHECK_FALSE(fits_datagram(datagram));
  Receiver receiver;
  CHECK(receiver.receive_datagram(datagram) == Reason::oversized);
  CHECK(receiver == Receiver{});
  payload.pop_back();
  CHECK(receiver.receive_datagram(widest_datagram(payload)) == Reason::ok);

  // A message over the limit is oversized on UDP whatever its type; TCP allows the size.
  Bytes message = widest_frame_data(payload);
  while (message.size() <= kMaxDatagram) {
    payload.push_back(0xEE);
    message = widest_frame_data(payload);
  }
  CHECK_FALSE(fits_datagram(message));
  CHECK(verify_message(message, kFromServerUdp).reason == Reason::oversized);
  VerifyOptions tcp = kFromServerUdp;
  tcp.transport = wire::Transport::tcp;
  CHECK(verify_message(message, tcp).ok);
}

TEST_CASE("no amplification: UdpHello is padded and UdpReady is smaller") {
  for (std::size_t cookie : {kMinCookieBytes, kMaxCookieBytes}) {
    const Bytes hello = encode(UdpHello{1, Bytes(cookie, 3)});
    CHECK(hello.size() >= kUdpHelloMinBytes);
    CHECK(hello.size() < kUdpHelloMinBytes + 16);
    CHECK(fits_datagram(hello));
    CHECK(verify_message(hello, from(Sender::client, wire::Transport::udp)).ok);
    const Bytes ready = encode(UdpReady{std::numeric_limits<std::uint64_t>::max()});
    CHECK(ready.size() <= hello.size());
    CHECK(message_datagram(ready).size() <= hello.size());  // as the server sends it: kind byte + message
  }
}

TEST_CASE("every message allowed on UDP fits a datagram with its largest fields") {
  const Bytes cookie(kMaxCookieBytes, 0xCC);
  const std::uint64_t big = std::numeric_limits<std::uint64_t>::max();
  const std::uint32_t seq = std::numeric_limits<std::uint32_t>::max();
  for (const Bytes& bytes : {encode(Ack{big, cookie, kLargestTick, seq}),
                             encode(KeyframeRequest{big, cookie, wire::KeyframeReason::incomplete_frame}),
                             encode(Ping{big, cookie, seq, big}), encode(UdpHello{big, cookie})})
    CHECK(fits_datagram(bytes));
  // The server's messages travel behind the kind byte.
  for (const Bytes& bytes : {encode(Pong{seq, big, kLargestTick, -1}), encode(UdpReady{big})}) {
    const Bytes datagram = message_datagram(bytes);
    CHECK(fits_datagram(datagram));
    REQUIRE(datagram.size() == bytes.size() + 1);
    CHECK(datagram[0] == static_cast<std::uint8_t>(DatagramKind::message));
    CHECK(std::equal(bytes.begin(), bytes.end(), datagram.begin() + 1));
    Receiver receiver;
    CHECK(receiver.receive_datagram(datagram) == Reason::ok);
    CHECK(receiver.messages == 1);
  }
}

TEST_CASE("a frames datagram carries the newest frame and earlier copies, oldest first, checked whole") {
  // The newest frame plus kMaxBundleChunks - 1 unacknowledged copies, as ocean-server sends them.
  const Bytes newest(600, 0x42), copy(60, 0x24);
  std::vector<FrameRecord> records;
  for (ocean::Tick tick = 1000 - (kMaxBundleChunks - 1); tick < 1000; ++tick)
    records.push_back(FrameRecord{tick, tick - 1, false, 0, 1, copy});
  records.push_back(FrameRecord{1000, 999, false, 0, 1, newest});
  REQUIRE(records.size() == kMaxBundleChunks);
  const Bytes datagram = frames_datagram(records);
  CHECK(fits_datagram(datagram));
  std::vector<FrameRecord> back;
  REQUIRE(decode_frame_block(std::span(datagram).subspan(1), back));
  CHECK(same_records(back, records));
  Receiver receiver;
  REQUIRE(receiver.receive_datagram(datagram) == Reason::ok);
  REQUIRE(receiver.seen.size() == kMaxBundleChunks);
  CHECK(receiver.seen.front().first == 1000 - (kMaxBundleChunks - 1));
  CHECK(receiver.seen.back().first == 1000);

  // FrameData is TCP only, and from the server only: UDP frames travel as frames datagrams.
  const Bytes message = encode(FrameData{encode_frame_block(records)});
  CHECK(verify_message(message, from_server()).ok);
  CHECK(verify_message(message, kFromServerUdp).reason == Reason::unexpected_message);
  CHECK(verify_message(message, from(Sender::client, wire::Transport::tcp)).reason == Reason::unexpected_message);

  // One bad record refuses the whole datagram: nothing of it is taken.
  // (encode_frame_block refuses to write an index >= count: the bad record is appended raw.)
  const Receiver before = receiver;
  Bytes broken = frames_datagram(std::span(records).first(3));
  broken.insert(broken.end(), {0, 1, 1, 2, 1, 0});  // back 0, lag 1, count-1 = 1, index 2, length 1, payload
  CHECK(receiver.receive_datagram(broken) == Reason::bad_chunk_index);
  CHECK(receiver == before);
  // An unknown kind byte is refused too.
  Bytes unknown_kind = datagram;
  unknown_kind[0] = 2;
  CHECK(receiver.receive_datagram(unknown_kind) == Reason::unknown_message_type);
  CHECK(receiver == before);
}
