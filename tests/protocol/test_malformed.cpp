// Every class of malformed input is rejected with its own reason, and a receiver that gets it
// is left exactly as it was.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "frame_blocks.hpp"
#include "message_builders.hpp"
#include "protocol_version.hpp"
#include "receiver.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;
namespace model = ocean::model;
using flatbuffers::FlatBufferBuilder;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Asserts the bytes are rejected for `reason` and that a busy receiver is unchanged by them.
void expect_rejected(std::span<const std::uint8_t> bytes, const VerifyOptions& options, Reason reason) {
  const Verified verified = verify_message(bytes, options);
  INFO("got " << describe(verified));
  CHECK_FALSE(verified.ok);
  CHECK(verified.message == nullptr);
  CHECK(verified.reason == reason);
  if (!verified.ok) CHECK_FALSE(verified.field.empty());

  Receiver receiver = busy_receiver();
  const Receiver before = receiver;
  CHECK(receiver.receive(bytes, options) == reason);
  CHECK(receiver == before);
}

void expect_rejected(const AnyMessage& message, const VerifyOptions& options, Reason reason) {
  expect_rejected(encode(message), options, reason);
}

// A FrameData message is verified as a message only (its block is present); the block's own rules
// are decode_frame_block's: the message passes the gate, the receiver refuses the block for
// `reason` and is left exactly as it was.
void expect_block_refused(const Bytes& block, Reason reason) {
  const Bytes bytes = encode(FrameData{block});
  const Verified verified = verify_message(bytes, from_server());
  INFO(describe(verified));
  REQUIRE(verified.ok);
  std::vector<FrameRecord> records;
  const FrameBlockResult parsed = decode_frame_block(block, records);
  INFO("block refused for: " << parsed.rule);
  CHECK(parsed.reason == reason);
  CHECK_FALSE(parsed.rule.empty());
  CHECK(records.empty());

  Receiver receiver = busy_receiver();
  const Receiver before = receiver;
  CHECK(receiver.receive(bytes, from_server()) == reason);
  CHECK(receiver == before);
}

// A version-1 frame message built by hand (the library no longer encodes them): a FrameChunk, or a
// FrameBundle of two such chunks. Every field is valid by version 1's rules.
Bytes version1_frame_message(wire::Body type) {
  FlatBufferBuilder fbb;
  auto chunk = [&fbb](std::uint32_t tick) {
    const std::uint8_t payload[] = {1, 2, 3};
    const auto bytes = fbb.CreateVector(payload, 3);
    wire::FrameChunkBuilder b(fbb);
    b.add_tick(tick);
    b.add_baseline(tick - 1);
    b.add_key(false);
    b.add_profile_id(1);
    b.add_index(0);
    b.add_count(1);
    b.add_payload(bytes);
    return b.Finish();
  };
  flatbuffers::Offset<void> body;
  if (type == wire::Body::FrameChunk) {
    body = chunk(1000).Union();
  } else {
    const std::vector<flatbuffers::Offset<wire::FrameChunk>> chunks{chunk(999), chunk(1000)};
    const auto vector = fbb.CreateVector(chunks);
    wire::FrameBundleBuilder b(fbb);
    b.add_chunks(vector);
    body = b.Finish().Union();
  }
  wire::MessageBuilder root(fbb);
  root.add_version(kProtocolVersion);
  root.add_body_type(type);
  root.add_body(body);
  wire::FinishSizePrefixedMessageBuffer(fbb, root.Finish());
  return Bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
}

// A Message root built by hand, for envelopes encode() never makes.
Bytes raw_message(std::uint16_t version, std::uint8_t body_type, bool with_body) {
  FlatBufferBuilder fbb;
  flatbuffers::Offset<void> body = 0;
  if (with_body) {
    wire::UdpReadyBuilder b(fbb);
    b.add_session_id(5);
    body = b.Finish().Union();
  }
  wire::MessageBuilder root(fbb);
  root.add_version(version);
  root.add_body_type(static_cast<wire::Body>(body_type));
  if (with_body) root.add_body(body);
  wire::FinishSizePrefixedMessageBuffer(fbb, root.Finish());
  return Bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
}

void write_i32(Bytes& bytes, std::size_t at, std::int32_t value) { std::memcpy(&bytes[at], &value, 4); }

}  // namespace

TEST_CASE("truncated input: every shorter prefix of a message is rejected") {
  const Bytes whole = encode(sample_welcome());
  expect_rejected(std::span<const std::uint8_t>(), from_server(), Reason::empty);
  for (std::size_t n = 1; n < whole.size(); ++n) {
    INFO("first " << n << " bytes");
    expect_rejected(aligned_copy(std::span(whole).first(n)), from_server(), Reason::truncated);
  }
}

TEST_CASE("oversized, trailing bytes, empty prefix, wrong identifier, misaligned") {
  const Bytes payload(3000, 7);
  const FrameRecord key{9, 9, true, 0, 1, payload};
  const Bytes big = encode(FrameData{encode_frame_block(std::span(&key, 1))});
  REQUIRE(verify_message(big, from_server()).ok);
  VerifyOptions small = from_server();
  small.max_message_bytes = 2000;
  expect_rejected(big, small, Reason::oversized);
  expect_rejected(big, from(Sender::server, wire::Transport::udp), Reason::oversized);  // size before type

  Bytes trailing = encode(sample_frame_data());
  trailing.push_back(0);
  expect_rejected(trailing, from_server(), Reason::trailing_bytes);

  Bytes zero_prefix = encode(sample_frame_data());
  write_i32(zero_prefix, 0, 0);
  expect_rejected(zero_prefix, from_server(), Reason::empty);

  Bytes wrong_id = encode(sample_frame_data());
  wrong_id[8] = 'X';
  expect_rejected(wrong_id, from_server(), Reason::bad_identifier);

  const Bytes good = encode(sample_frame_data());
  Bytes shifted(good.size() + 1);
  std::memcpy(shifted.data() + 1, good.data(), good.size());
  expect_rejected(std::span(shifted).subspan(1), from_server(), Reason::misaligned_buffer);
}

TEST_CASE("bad offsets: corrupt vtable offsets and vector lengths fail the Verifier") {
  const Bytes good = encode(sample_frame_data());
  const auto* message = wire::GetSizePrefixedMessage(good.data());
  const std::size_t root_table = 4 + flatbuffers::ReadScalar<std::uint32_t>(good.data() + 4);
  const std::size_t body_table = reinterpret_cast<const std::uint8_t*>(message->body()) - good.data();
  const std::size_t frames_vector =
      reinterpret_cast<const std::uint8_t*>(message->body_as_FrameData()->frames()) - good.data();

  Bytes root_vtable = good;
  write_i32(root_vtable, root_table, 0x7ffffff0);
  expect_rejected(root_vtable, from_server(), Reason::bad_verifier);

  Bytes body_vtable = good;
  write_i32(body_vtable, body_table, -100000);
  expect_rejected(body_vtable, from_server(), Reason::bad_verifier);

  Bytes odd_vtable = good;  // vtable offset not 2-byte aligned
  write_i32(odd_vtable, body_table, flatbuffers::ReadScalar<std::int32_t>(&good[body_table]) + 1);
  expect_rejected(odd_vtable, from_server(), Reason::bad_verifier);

  Bytes vector_length = good;
  write_i32(vector_length, frames_vector, 0x00ffffff);
  expect_rejected(vector_length, from_server(), Reason::bad_verifier);

  Bytes root_offset = good;
  write_i32(root_offset, 4, static_cast<std::int32_t>(good.size() + 64));
  expect_rejected(root_offset, from_server(), Reason::bad_verifier);
}

TEST_CASE("envelope: unknown version, unknown or missing body") {
  const VerifyOptions udp = from(Sender::server, wire::Transport::udp);  // the body is a UdpReady
  REQUIRE(verify_message(raw_message(kProtocolVersion, 4, true), udp).ok);
  expect_rejected(raw_message(kProtocolVersion + 1, 4, true), udp, Reason::unknown_version);
  expect_rejected(raw_message(0, 4, true), udp, Reason::unknown_version);
  expect_rejected(raw_message(kProtocolVersion, 0, false), udp, Reason::unknown_message_type);
  expect_rejected(raw_message(kProtocolVersion, 99, true), udp, Reason::unknown_message_type);
  expect_rejected(raw_message(kProtocolVersion, 4, false), udp, Reason::missing_field);
}

TEST_CASE("unexpected message: wrong sender or wrong transport") {
  expect_rejected(sample_welcome(), from_client(), Reason::unexpected_message);
  expect_rejected(sample_frame_data(), from_client(), Reason::unexpected_message);
  expect_rejected(sample_frame_data(), from(Sender::server, wire::Transport::udp), Reason::unexpected_message);  // TCP only
  expect_rejected(Hello{}, from_server(), Reason::unexpected_message);
  expect_rejected(Hello{}, from(Sender::client, wire::Transport::udp), Reason::unexpected_message);
  expect_rejected(UdpHello{1, sample_cookie()}, from_client(), Reason::unexpected_message);
}

TEST_CASE("version 1 frame messages: FrameChunk and FrameBundle are refused as unexpected") {
  for (wire::Body type : {wire::Body::FrameChunk, wire::Body::FrameBundle}) {
    INFO(wire::EnumNameBody(type));
    const Bytes bytes = version1_frame_message(type);
    // Well-formed FlatBuffers of ocean.fbs: the refusal is the version's, not the Verifier's.
    flatbuffers::Verifier verifier(bytes.data(), bytes.size());
    REQUIRE(wire::VerifySizePrefixedMessageBuffer(verifier));
    CHECK_FALSE(may_send(Sender::server, type));
    CHECK_FALSE(may_send(Sender::client, type));
    for (Sender sender : {Sender::server, Sender::client})
      for (wire::Transport transport : {wire::Transport::udp, wire::Transport::tcp})
        expect_rejected(bytes, from(sender, transport), Reason::unexpected_message);
  }
}

TEST_CASE("profiles: unknown ids are rejected") {
  expect_rejected(Hello{200, 0, wire::Transport::tcp, ""}, from_client(), Reason::unknown_profile);

  Welcome welcome = sample_welcome();
  welcome.offered_profiles = {1, 77};
  expect_rejected(welcome, from_server(), Reason::unknown_profile);
  welcome.offered_profiles = {2, 4};  // stream profile 1 not among them
  expect_rejected(welcome, from_server(), Reason::unknown_profile);
}

TEST_CASE("dimensions: grid, flags, scene size and vector lengths must agree") {
  Welcome welcome = sample_welcome();
  welcome.stream.grid = 128;  // profile 1 is 64
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);

  welcome = sample_welcome();
  welcome.stream.choppy = true;  // profile 1 is not choppy
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);

  welcome = sample_welcome();
  welcome.scene.size_x = 100;  // not a power of two
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);

  welcome = sample_welcome();
  welcome.stream = StreamParams{3, 256, 256, 256, 9.81, 0, 30, 0.01f, 1.0f / 256, 0.01f, true, true, {}, {}};
  welcome.offered_profiles = {3};
  welcome.scene.size_z = 128;  // a 256 stream cannot come from a 128-row scene
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);

  welcome = sample_welcome();
  welcome.offered_profiles.clear();
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);
  welcome.offered_profiles.assign(17, 1);
  expect_rejected(welcome, from_server(), Reason::bad_dimensions);
}

TEST_CASE("FrameData: the frames block must be present and not empty") {
  // Built by hand: encode() writes no vector for an empty block, and FrameDataBuilder::Finish()
  // asserts that the required field is there.
  const auto frame_data = [](bool with_vector) {
    FlatBufferBuilder fbb;
    const auto frames = fbb.CreateVector(static_cast<const std::uint8_t*>(nullptr), 0);
    const auto start = fbb.StartTable();
    if (with_vector) fbb.AddOffset(wire::FrameData::VT_FRAMES, frames);
    const flatbuffers::Offset<void> body(fbb.EndTable(start));
    wire::MessageBuilder root(fbb);
    root.add_version(kProtocolVersion);
    root.add_body_type(wire::Body::FrameData);
    root.add_body(body);
    wire::FinishSizePrefixedMessageBuffer(fbb, root.Finish());
    return Bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
  };
  const Bytes empty = frame_data(true);
  expect_rejected(empty, from_server(), Reason::missing_field);
  CHECK(verify_message(empty, from_server()).field == "FrameData.frames");
  // Absent altogether: the schema marks frames required, so the FlatBuffers Verifier refuses it first.
  expect_rejected(frame_data(false), from_server(), Reason::bad_verifier);
}

TEST_CASE("sequence: a record's tick and lag must be consistent") {
  // newest 5000: a record 5001 ticks back would be before tick 0.
  expect_block_refused(RawBlock().v(5000).record(5001, 0).bytes, Reason::bad_sequence);
  // lag (tick - baseline) beyond kMaxFrameLag, and beyond the tick itself (baseline < 0).
  expect_block_refused(RawBlock().v(5000).record(0, kMaxFrameLag + 1).bytes, Reason::bad_sequence);
  expect_block_refused(RawBlock().v(10).record(0, 11).bytes, Reason::bad_sequence);
  expect_block_refused(RawBlock().v(5000).record(0, 1).record(4990, 11).bytes, Reason::bad_sequence);  // second one
  // The edges are fine.
  std::vector<FrameRecord> records;
  REQUIRE(decode_frame_block(RawBlock().v(5000).record(0, kMaxFrameLag).bytes, records));
  CHECK(records.at(0).baseline == 5000 - kMaxFrameLag);
  CHECK_FALSE(records.at(0).key);
  REQUIRE(decode_frame_block(RawBlock().v(10).record(0, 10).bytes, records));
  CHECK(records.at(0).baseline == 0);
  REQUIRE(decode_frame_block(RawBlock().v(5000).record(5000, 0).bytes, records));
  CHECK(records.at(0).tick == 0);
  CHECK(records.at(0).key);
}

TEST_CASE("chunk index: count >= 1, index < count, count bounded") {
  const auto chunk = [](std::uint64_t count_minus_1, std::uint64_t index) {
    return RawBlock().v(1000).v(0).v(2).v(count_minus_1).v(index).v(3).payload(3).bytes;
  };
  expect_block_refused(chunk(4, 5), Reason::bad_chunk_index);                       // index 5 of 5
  expect_block_refused(chunk(0xFFFF'FFFFu, 0), Reason::bad_chunk_index);           // count 0, as (count - 1) wraps
  expect_block_refused(chunk(kMaxChunksPerFrame, 0), Reason::bad_chunk_index);     // count 4097
  std::vector<FrameRecord> records;
  REQUIRE(decode_frame_block(chunk(kMaxChunksPerFrame - 1, kMaxChunksPerFrame - 1), records));
  CHECK(records.at(0).count == kMaxChunksPerFrame);
  CHECK(records.at(0).index == kMaxChunksPerFrame - 1);
}

TEST_CASE("non-finite values: NaN and infinity in any float field") {
  Welcome welcome = sample_welcome();
  welcome.scene.wind_speed_mps = kNaN;
  expect_rejected(welcome, from_server(), Reason::non_finite_value);
  welcome = sample_welcome();
  welcome.stream.patch_x_m = kInf;
  expect_rejected(welcome, from_server(), Reason::non_finite_value);
  welcome = sample_welcome();
  welcome.stream.height_step_m = std::numeric_limits<float>::quiet_NaN();
  expect_rejected(welcome, from_server(), Reason::non_finite_value);
  welcome = sample_welcome();
  welcome.tick_period_s = kNaN;
  expect_rejected(welcome, from_server(), Reason::non_finite_value);

  ParamChange change = sample_param_change();
  change.amplitude = -kInf;
  expect_rejected(change, from_client(), Reason::non_finite_value);
  expect_rejected(SceneUpdate{0, 5, [] { auto s = sample_scene(); s.gravity_mps2 = kNaN; return s; }(), 1},
                  from_server(), Reason::non_finite_value);
}

TEST_CASE("out of range: finite numbers outside their documented ranges") {
  Welcome welcome = sample_welcome();
  welcome.stream.rate_hz = 0;
  expect_rejected(welcome, from_server(), Reason::out_of_range);
  welcome = sample_welcome();
  welcome.scene.choppiness = -1;
  expect_rejected(welcome, from_server(), Reason::out_of_range);
  welcome = sample_welcome();
  welcome.max_message_bytes = 100;
  expect_rejected(welcome, from_server(), Reason::out_of_range);
  welcome = sample_welcome();
  welcome.stream.slope_step = 0.0f;
  expect_rejected(welcome, from_server(), Reason::out_of_range);

  ParamChange change = sample_param_change();
  change.wind_speed_mps = -3.0;
  expect_rejected(change, from_client(), Reason::out_of_range);
}

TEST_CASE("enums: values the schema does not define") {
  expect_rejected(Hello{1, 0, static_cast<wire::Transport>(7), ""}, from_client(), Reason::bad_enum);
  expect_rejected(Error{static_cast<Reason>(200), "x"}, from_server(), Reason::bad_enum);
  expect_rejected(Bye{static_cast<wire::ByeReason>(9), ""}, from_client(), Reason::bad_enum);
  expect_rejected(SetTransport{static_cast<wire::Transport>(2)}, from_client(), Reason::bad_enum);
  expect_rejected(KeyframeRequest{1, {}, static_cast<wire::KeyframeReason>(50)}, from_client(), Reason::bad_enum);
  Welcome welcome = sample_welcome();
  welcome.scene.spectrum = static_cast<model::SpectrumKind>(3);
  expect_rejected(welcome, from_server(), Reason::bad_enum);
  ParamChange change = sample_param_change();
  change.spectrum = static_cast<wire::Spectrum>(5);
  expect_rejected(change, from_client(), Reason::bad_enum);
}

TEST_CASE("strings: length limits and UTF-8") {
  expect_rejected(Hello{1, 0, wire::Transport::tcp, std::string(kMaxClientNameBytes + 1, 'a')},
                  from_client(), Reason::bad_string);
  CHECK(verify_message(encode(Hello{1, 0, wire::Transport::tcp, std::string(kMaxClientNameBytes, 'a')}),
                       from_client()).ok);
  for (const char* bad : {"\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80", "ok\xf4\x90\x80\x80"}) {
    INFO("string " << bad);
    expect_rejected(Bye{wire::ByeReason::kicked, bad}, from_server(), Reason::bad_string);
  }
  expect_rejected(Error{Reason::timeout, std::string(kMaxTextBytes + 1, 'e')}, from_server(), Reason::bad_string);
  ParamChange change = sample_param_change();
  change.admin_token.clear();
  expect_rejected(change, from_client(), Reason::missing_field);
  change = sample_param_change();
  change.wind_speed_mps.reset();
  change.choppiness.reset();
  change.spectrum.reset();
  expect_rejected(change, from_client(), Reason::missing_field);
}

TEST_CASE("sessions and cookies") {
  const auto udp = from(Sender::client, wire::Transport::udp);
  expect_rejected(Ack{0, sample_cookie(), 1, 0}, udp, Reason::bad_session);
  expect_rejected(Ack{5, {}, 1, 0}, udp, Reason::bad_cookie);  // required on UDP
  CHECK(verify_message(encode(Ack{5, {}, 1, 0}), from_client()).ok);  // not on TCP
  expect_rejected(Ping{5, Bytes(3, 1), 1, 1}, udp, Reason::bad_cookie);
  expect_rejected(UdpHello{5, Bytes(kMaxCookieBytes + 1, 1)}, udp, Reason::bad_cookie);

  Welcome welcome = sample_welcome();
  welcome.udp_cookie.clear();  // UDP offered without a cookie
  expect_rejected(welcome, from_server(), Reason::bad_cookie);
  welcome.udp_port = 0;  // no UDP: no cookie is right
  CHECK(verify_message(encode(welcome), from_server()).ok);
  welcome.udp_cookie = sample_cookie();  // no UDP but a cookie
  expect_rejected(welcome, from_server(), Reason::bad_cookie);
  welcome = sample_welcome();
  welcome.session_id = 0;
  expect_rejected(welcome, from_server(), Reason::bad_session);
}

TEST_CASE("check_udp_sender compares session and cookie") {
  const Bytes bytes = encode(Ack{5, sample_cookie(), 1, 0});
  const Verified v = verify_message(bytes, from(Sender::client, wire::Transport::udp));
  REQUIRE(v.ok);
  CHECK(check_udp_sender(*v.message, 5, sample_cookie()) == Reason::ok);
  CHECK(check_udp_sender(*v.message, 6, sample_cookie()) == Reason::bad_session);
  Bytes other = sample_cookie();
  other.back() ^= 1;
  CHECK(check_udp_sender(*v.message, 5, other) == Reason::bad_cookie);
  CHECK(check_udp_sender(*v.message, 5, Bytes(sample_cookie().size() - 1, 1)) == Reason::bad_cookie);
  const Bytes pong = encode(Pong{});
  CHECK(check_udp_sender(*verify_message(pong, from_server()).message, 5, other) == Reason::unexpected_message);
}

TEST_CASE("UdpHello without padding is refused: answering it could amplify") {
  FlatBufferBuilder fbb;
  const auto cookie = fbb.CreateVector(sample_cookie());
  wire::UdpHelloBuilder b(fbb);
  b.add_session_id(5);
  b.add_cookie(cookie);
  const auto body = b.Finish();
  wire::MessageBuilder root(fbb);
  root.add_version(kProtocolVersion);
  root.add_body_type(wire::Body::UdpHello);
  root.add_body(body.Union());
  wire::FinishSizePrefixedMessageBuffer(fbb, root.Finish());
  const Bytes bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
  REQUIRE(bytes.size() < kUdpHelloMinBytes);
  expect_rejected(bytes, from(Sender::client, wire::Transport::udp), Reason::unpadded_udp_hello);
}

TEST_CASE("range edges: the sim's own limits are accepted, one step beyond is not") {
  auto scene_with = [](auto edit) {
    SceneParams scene;  // the sim's defaults
    edit(scene);
    return encode(SceneUpdate{0, 1, scene, 1});
  };
  CHECK(verify_message(scene_with([](SceneParams&) {}), from_server()).ok);
  CHECK(verify_message(scene_with([](SceneParams& s) { s.choppiness = model::kMaxChoppiness; }), from_server()).ok);
  CHECK(verify_message(scene_with([](SceneParams& s) { s.gravity_mps2 = model::kMinGravityMps2; }), from_server()).ok);
  CHECK(verify_message(scene_with([](SceneParams& s) { s.size_x = model::kMaxSceneSize; }), from_server()).ok);
  CHECK(verify_message(scene_with([](SceneParams& s) { s.wind_dir_deg = -model::kMaxWindDirDeg; }), from_server()).ok);
  const auto beyond = [](double x) { return std::nextafter(x, HUGE_VAL); };
  expect_rejected(scene_with([&](SceneParams& s) { s.choppiness = beyond(model::kMaxChoppiness); }), from_server(),
                  Reason::out_of_range);
  expect_rejected(scene_with([&](SceneParams& s) { s.fetch_m = std::nextafter(model::kMinFetchM, 0.0); }), from_server(),
                  Reason::out_of_range);
  expect_rejected(scene_with([&](SceneParams& s) { s.wind_speed_mps = beyond(model::kMaxWindSpeedMps); }), from_server(),
                  Reason::out_of_range);
  expect_rejected(scene_with([](SceneParams& s) { s.size_z = 4096; }), from_server(), Reason::bad_dimensions);
  expect_rejected(scene_with([](SceneParams& s) { s.depth_m = -1; }), from_server(), Reason::out_of_range);
}

TEST_CASE("Welcome vessels: counts, tracks and presences at their limits are accepted, beyond them refused") {
  const double inf = std::numeric_limits<double>::infinity();
  // The most a Welcome may carry: 32 vessels of 64 waypoints at 20 m/s, the largest hulls, at the
  // world's edge, each with a presence.
  auto fleet = [] {
    Welcome w = sample_welcome();
    w.stream.wake = ocean::WakeLattice{64, 8192.0, -4096.0, -4096.0, 10.0, 1.0, 1800};
    for (std::uint32_t id = 1; id <= 32; ++id) {
      ocean::model::VesselTrack v;
      v.id = id;
      v.hull = {400.0, 400.0, 25.0};
      for (int i = 0; i < 64; ++i) v.points.push_back({20.0 * i, -1e7 + 400.0 * i, 1e7});
      v.presence = {-1e12, 1e12, 1e12};
      w.vessels.push_back(v);
    }
    return w;
  };
  CHECK(verify_message(encode(fleet()), from_server()).ok);
  const auto refused = [&](auto edit, Reason reason) {
    Welcome w = fleet();
    edit(w);
    expect_rejected(encode(w), from_server(), reason);
  };
  refused([](Welcome& w) { w.vessels.push_back(w.vessels.back()); }, Reason::bad_dimensions);
  refused([](Welcome& w) { w.vessels[3].points.push_back({2000.0, 0.0, 0.0}); }, Reason::bad_dimensions);
  refused([](Welcome& w) { w.vessels[3].points.clear(); }, Reason::bad_dimensions);
  refused([](Welcome& w) { w.stream.wake = ocean::WakeLattice{}; }, Reason::bad_dimensions);  // grid 0: no wake
  refused([](Welcome& w) { w.vessels[5].points[7].t_s -= 0.01; }, Reason::out_of_range);  // 400 m in 19.99 s
  refused([](Welcome& w) { w.vessels[5].hull.draft_m = std::nextafter(25.0, 30.0); }, Reason::out_of_range);
  refused([](Welcome& w) { w.vessels[0].presence.from_s = std::nan(""); }, Reason::out_of_range);
  refused([](Welcome& w) { w.vessels[0].presence.for_s = 0.0; }, Reason::out_of_range);
  refused([=](Welcome& w) { w.vessels[0].presence = {-inf, 5.0, 0.0}; }, Reason::out_of_range);
  refused([](Welcome& w) { w.vessels[31].presence.every_s = std::nextafter(1e12, 0.0); }, Reason::out_of_range);
}

TEST_CASE("vessel commands and fleets in SceneUpdates: malformed ones are refused, naming the field", "[vessels]") {
  ParamChange change;
  change.admin_token = "token";
  change.vessel = VesselCommand{wire::VesselAction::course, 7, {24.0, 6.0, 1.5}, 0.0, 0.0, 90.0, 20.0, 2.0};
  CHECK(verify_message(encode(change), from_client()).ok);  // a vessel command alone is a change
  const auto refused = [&](auto edit, Reason reason) {
    ParamChange c = change;
    edit(*c.vessel);
    expect_rejected(encode(c), from_client(), reason);
  };
  refused([](VesselCommand& v) { v.action = wire::VesselAction::none; }, Reason::missing_field);
  refused([](VesselCommand& v) { v.action = static_cast<wire::VesselAction>(9); }, Reason::bad_enum);
  refused([](VesselCommand& v) { v.speed_mps = std::nan(""); }, Reason::non_finite_value);
  refused([](VesselCommand& v) { v.x_m = std::numeric_limits<double>::infinity(); }, Reason::non_finite_value);
  refused([](VesselCommand& v) { v.hull.draft_m = -std::numeric_limits<double>::infinity(); }, Reason::non_finite_value);

  // A SceneUpdate's fleet: the Welcome's limits.
  ocean::model::VesselTrack v;
  v.hull = {24.0, 6.0, 1.5};
  v.points = {{0.0, 10.0, 10.0}};
  SceneUpdate update{0, 100, sample_scene(), 3};
  update.vessels = std::vector<ocean::model::VesselTrack>(32, v);
  CHECK(verify_message(encode(update), from_server()).ok);
  update.vessels->push_back(v);
  expect_rejected(encode(update), from_server(), Reason::bad_dimensions);
  update.vessels = std::vector<ocean::model::VesselTrack>{v};
  update.vessels->front().presence = {5.0, 0.0, 0.0};
  expect_rejected(encode(update), from_server(), Reason::out_of_range);
  update.vessels = std::vector<ocean::model::VesselTrack>{};  // an empty fleet: every vessel gone
  CHECK(verify_message(encode(update), from_server()).ok);
}
