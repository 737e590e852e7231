// Every message type survives encode -> verify -> decode unchanged, on every transport it may use.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "protocol_version.hpp"
#include "sample_messages.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;

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
  // One sample per union member: a new message type must get a sample here.
  CHECK(seen.size() == static_cast<std::size_t>(wire::Body::MAX));
}

TEST_CASE("size prefix is little-endian and counts the bytes after it") {
  const Bytes bytes = encode(sample_chunk());
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

TEST_CASE("split_frame cuts a payload into chunks that reassemble in order") {
  Bytes payload(2500);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 7);
  const FrameHeader header{50, 50, true, 2};
  const std::vector<Bytes> chunks = split_frame(header, payload, 1000);
  REQUIRE(chunks.size() == 3);
  Bytes joined;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const Verified verified = verify_message(chunks[i], from_server());
    REQUIRE(verified.ok);
    const FrameChunk chunk = std::get<FrameChunk>(decode(*verified.message));
    CHECK(chunk.frame == header);
    CHECK(chunk.index == i);
    CHECK(chunk.count == 3);
    joined.insert(joined.end(), chunk.payload.begin(), chunk.payload.end());
  }
  CHECK(joined == payload);
  CHECK(split_frame(header, {}, 1000).size() == 1);
  CHECK(split_frame(header, payload, 0).empty());
  CHECK(split_frame(header, Bytes(kMaxChunksPerFrame + 1), 1).empty());
}

TEST_CASE("the example bytes in PROTOCOL.md decode to the Ping it describes") {
  const Bytes example = {
      0x5c, 0x00, 0x00, 0x00, 0x18, 0x00, 0x00, 0x00, 0x4f, 0x43, 0x4e, 0x50, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x0a, 0x00, 0x0c, 0x00, 0x0a, 0x00, 0x09, 0x00, 0x04, 0x00, 0x0a, 0x00, 0x00, 0x00,
      0x14, 0x00, 0x00, 0x00, 0x00, 0x0d, 0x01, 0x00, 0x0c, 0x00, 0x20, 0x00, 0x14, 0x00, 0x10, 0x00,
      0x0c, 0x00, 0x04, 0x00, 0x0c, 0x00, 0x00, 0x00, 0xe8, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01,
      0x00, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0xa0, 0xa1, 0xa2, 0xa3, 0xa4, 0xa5, 0xa6, 0xa7};
  const Verified verified = verify_message(example, from(Sender::client, wire::Transport::udp));
  INFO(describe(verified));
  REQUIRE(verified.ok);
  const Ping expected{0x0102030405060708ull, Bytes{0xa0, 0xa1, 0xa2, 0xa3, 0xa4, 0xa5, 0xa6, 0xa7}, 1, 1000};
  CHECK(std::get<Ping>(decode(*verified.message)) == expected);
}
