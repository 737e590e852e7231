// Every message type survives encode -> verify -> decode unchanged, on every transport it may use.
#include <catch2/catch.hpp>

#include <limits>
#include <set>
#include <string>

#include "frame_blocks.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "protocol_version.hpp"
#include "sample_messages.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;
using ocean::Tick;

namespace {

wire::Body body_type_of(const Bytes& bytes) {
  return wire::GetSizePrefixedMessage(bytes.data())->body_type();
}

}  // namespace

TEST_CASE("every message type round-trips through encode, verify and decode") {
  std::set<wire::Body> seen;
  for (const Sample& sample : all_samples()) {
    const Bytes bytes = encode(sample.message);
    const wire::Body type = body_type_of(bytes);
    seen.insert(type);
    INFO("message " << wire::EnumNameBody(type));
    for (wire::Transport transport : {wire::Transport::tcp, wire::Transport::udp}) {
      if (!may_travel(transport, type)) continue;
      const Verified verified = verify_message(bytes, from(sample.sender, transport));
      INFO("transport " << wire::EnumNameTransport(transport) << ": " << describe(verified));
      REQUIRE(verified.ok);
      REQUIRE(verified.reason == Reason::ok);
      REQUIRE(verified.message != nullptr);
      CHECK(verified.message->version() == kProtocolVersion);
      CHECK(decode(*verified.message) == sample.message);
    }
  }
  // One sample per union member of version 4: a new message type must get a sample here. The
  // version-1 frame messages are members still, but no version-2 peer sends or accepts them.
  for (auto b = static_cast<std::uint8_t>(wire::Body::NONE) + 1; b <= static_cast<std::uint8_t>(wire::Body::MAX); ++b) {
    const auto type = static_cast<wire::Body>(b);
    INFO("union member " << wire::EnumNameBody(type));
    const bool version1_only = type == wire::Body::FrameChunk || type == wire::Body::FrameBundle;
    CHECK(seen.count(type) == (version1_only ? 0u : 1u));
  }
  CHECK(seen.size() == static_cast<std::size_t>(wire::Body::MAX) - 2);
}

TEST_CASE("ticks are 64-bit: values past 2^32 survive, in the version-2 fields only") {
  const Tick far = (Tick{1} << 40) + 7;
  const Tick largest = std::numeric_limits<Tick>::max();
  for (Tick tick : {Tick{0xFFFF'FFFFu}, Tick{0x1'0000'0000u}, far, largest}) {
    INFO("tick " << tick);
    Welcome welcome = sample_welcome();
    welcome.current_tick = tick;
    const Bytes w = encode(welcome);
    const Verified vw = verify_message(w, from_server());
    REQUIRE(vw.ok);
    CHECK(std::get<Welcome>(decode(*vw.message)).current_tick == tick);
    CHECK(vw.message->body_as_Welcome()->current_tick() == 0);  // the version-1 field is not written
    CHECK(vw.message->body_as_Welcome()->current_tick64() == tick);

    const Bytes a = encode(Ack{5, sample_cookie(), tick, 1});
    const Verified va = verify_message(a, from(Sender::client, wire::Transport::udp));
    REQUIRE(va.ok);
    CHECK(std::get<Ack>(decode(*va.message)).latest_tick == tick);
    CHECK(va.message->body_as_Ack()->latest_tick() == 0);

    const Bytes u = encode(SceneUpdate{0, tick, sample_scene(), 9});
    const Verified vu = verify_message(u, from_server());
    REQUIRE(vu.ok);
    CHECK(std::get<SceneUpdate>(decode(*vu.message)).effective_tick == tick);
    CHECK(vu.message->body_as_SceneUpdate()->effective_tick() == 0);

    const Bytes p = encode(Pong{1, 2, tick, 3});
    const Verified vp = verify_message(p, from(Sender::server, wire::Transport::udp));
    REQUIRE(vp.ok);
    CHECK(std::get<Pong>(decode(*vp.message)).server_tick == tick);
    CHECK(vp.message->body_as_Pong()->server_tick() == 0);
  }
}

TEST_CASE("scene serials travel in Welcome and SceneUpdate") {
  Welcome welcome = sample_welcome();
  welcome.scene_serial = 0xFFFF'FFFFu;
  const Bytes w = encode(welcome);
  const Verified vw = verify_message(w, from_server());
  REQUIRE(vw.ok);
  CHECK(std::get<Welcome>(decode(*vw.message)).scene_serial == 0xFFFF'FFFFu);
  const SceneUpdate update{3, 900, sample_scene(), 257};
  const Bytes bytes = encode(update);
  const Verified vu = verify_message(bytes, from_server());
  REQUIRE(vu.ok);
  CHECK(std::get<SceneUpdate>(decode(*vu.message)) == update);
}

TEST_CASE("size prefix is little-endian and counts the bytes after it") {
  const Bytes bytes = encode(sample_frame_data());
  const std::uint32_t prefix = bytes[0] | bytes[1] << 8 | bytes[2] << 16 | std::uint32_t{bytes[3]} << 24;
  CHECK(prefix == bytes.size() - 4);
  CHECK(std::string(bytes.begin() + 8, bytes.begin() + 12) == kFileIdentifier);
}

TEST_CASE("absent optional ParamChange fields stay absent") {
  ParamChange change;
  change.admin_token = "token";
  change.wind_dir_deg = -45.0;
  const Bytes bytes = encode(change);
  const Verified verified = verify_message(bytes, from_client());
  REQUIRE(verified.ok);
  const auto* wire_change = verified.message->body_as_ParamChange();
  CHECK_FALSE(wire_change->wind_speed_mps().has_value());
  CHECK(wire_change->wind_dir_deg().value() == -45.0);
  CHECK(std::get<ParamChange>(decode(*verified.message)) == change);
}

TEST_CASE("each reason has a distinct name equal to the schema's ErrorCode name") {
  std::set<std::string> names;
  for (std::uint8_t i = 0; i < kReasonCount; ++i) {
    const auto reason = static_cast<Reason>(i);
    const std::string name(to_string(reason));
    CHECK(name == wire::EnumNameErrorCode(to_wire(reason)));
    names.insert(name);
  }
  CHECK(names.size() == kReasonCount);
  CHECK(to_string(static_cast<Reason>(200)) == "unknown_reason");
}

TEST_CASE("a frame cut into records travels in FrameData and reassembles in order") {
  Bytes payload(2500);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 7);
  std::vector<FrameRecord> chunks;
  for (std::uint16_t i = 0; i < 3; ++i)
    chunks.push_back(FrameRecord{50, 50, true, i, 3, std::span(payload).subspan(i * 1000u, i == 2 ? 500u : 1000u)});
  const Bytes bytes = encode(FrameData{encode_frame_block(chunks)});
  const Verified verified = verify_message(bytes, from_server());
  REQUIRE(verified.ok);
  const FrameData data = std::get<FrameData>(decode(*verified.message));
  std::vector<FrameRecord> records;
  REQUIRE(decode_frame_block(data.frames, records));
  REQUIRE(records.size() == 3);
  Bytes joined;
  for (std::size_t i = 0; i < records.size(); ++i) {
    INFO("record " << i);
    CHECK(same_record(records[i], chunks[i]));
    CHECK(records[i].index == i);
    CHECK(records[i].count == 3);
    CHECK(records[i].key);
    joined.insert(joined.end(), records[i].payload.begin(), records[i].payload.end());
  }
  CHECK(joined == payload);
  // The message's block is the very bytes of a frames datagram after its kind byte.
  const Bytes datagram = frames_datagram(chunks);
  CHECK(Bytes(datagram.begin() + 1, datagram.end()) == data.frames);
}

TEST_CASE("the example bytes in PROTOCOL.md decode to the Ping it describes (version 4)") {
  const Bytes example = {
      0x5c, 0x00, 0x00, 0x00, 0x18, 0x00, 0x00, 0x00, 0x4f, 0x43, 0x4e, 0x50, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x0a, 0x00, 0x0c, 0x00, 0x0a, 0x00, 0x09, 0x00, 0x04, 0x00, 0x0a, 0x00, 0x00, 0x00,
      0x14, 0x00, 0x00, 0x00, 0x00, 0x0d, 0x04, 0x00, 0x0c, 0x00, 0x20, 0x00, 0x14, 0x00, 0x10, 0x00,
      0x0c, 0x00, 0x04, 0x00, 0x0c, 0x00, 0x00, 0x00, 0xe8, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01,
      0x00, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0xa0, 0xa1, 0xa2, 0xa3, 0xa4, 0xa5, 0xa6, 0xa7};
  const Verified verified = verify_message(example, from(Sender::client, wire::Transport::udp));
  INFO(describe(verified));
  REQUIRE(verified.ok);
  const Ping expected{0x0102030405060708ull, Bytes{0xa0, 0xa1, 0xa2, 0xa3, 0xa4, 0xa5, 0xa6, 0xa7}, 1, 1000};
  CHECK(std::get<Ping>(decode(*verified.message)) == expected);
  CHECK(verified.message->version() == 4);  // byte 38
  CHECK(encode(expected) == example);       // "as the C++ library encodes it"
}
