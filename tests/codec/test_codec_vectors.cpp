// The committed codec test vectors (tests/codec/vectors, CODEC.md section 12) decode bit for bit:
// each file is read the way a client in another language would read it - the Welcome and
// SceneUpdate messages through verify_message, each chunk through its frames datagram
// (PROTOCOL.md 7), a codec::Decoder configured like ClientSession's - and every refusal, state
// hash and shown frame must be exactly the file's.
#include "codec_vectors.hpp"

#include "decoder.hpp"
#include "frame_records.hpp"
#include "message_readers.hpp"
#include "state_hash.hpp"
#include "stream_wire.hpp"
#include "verify_message.hpp"
#include "wire_limits.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <utility>
#include <fstream>
#include <iterator>
#include <memory>

using namespace ocean;
using namespace ocean::codec;
using namespace ocean::codec::vectors;

namespace {

std::string vectors_dir() { return OCEAN_CODEC_VECTORS_DIR; }

// verify_message needs an 8-byte aligned buffer.
struct Aligned {
  std::vector<std::uint64_t> words;
  std::size_t size;
  explicit Aligned(const std::vector<std::uint8_t>& bytes) : words((bytes.size() + 7) / 8), size(bytes.size()) {
    std::memcpy(words.data(), bytes.data(), bytes.size());
  }
  std::span<const std::uint8_t> span() const { return {reinterpret_cast<const std::uint8_t*>(words.data()), size}; }
};

const wire::Message& verified(const Aligned& bytes) {
  const protocol::Verified v = protocol::verify_message(
      bytes.span(), {protocol::Sender::server, wire::Transport::tcp, protocol::kDefaultMaxMessageBytes});
  INFO(protocol::describe(v));
  REQUIRE(v.ok);
  return *v.message;
}

void check_scene_line(const Line& line, Tick from, std::uint32_t serial, const protocol::SceneParams& s) {
  INFO("line " << line.number);
  CHECK(line.u64("from") == from);
  CHECK(line.u64("serial") == serial);
  CHECK(line.u64("tag") == serial % 256);
  CHECK(line.u64("size_x") == static_cast<std::uint64_t>(s.size_x));
  CHECK(line.u64("size_z") == static_cast<std::uint64_t>(s.size_z));
  CHECK(line.f64("patch_x_m") == s.patch_x_m);
  CHECK(line.f64("patch_z_m") == s.patch_z_m);
  CHECK(line.u64("spectrum") == static_cast<std::uint64_t>(s.spectrum));
  CHECK(line.u64("spreading") == static_cast<std::uint64_t>(s.spreading));
  CHECK(line.f64("wind_speed_mps") == s.wind_speed_mps);
  CHECK(line.f64("wind_dir_deg") == s.wind_dir_deg);
  CHECK(line.f64("fetch_m") == s.fetch_m);
  CHECK(line.f64("amplitude") == s.amplitude);
  CHECK(line.f64("depth_m") == model::wire_depth(s.depth_m));  // the wire's: 0 = deep
  CHECK(line.f64("small_wave_m") == s.small_wave_m);
  CHECK(line.f64("choppiness") == s.choppiness);
  CHECK(line.f64("gravity_mps2") == s.gravity_mps2);
  CHECK(line.u64("seed") == s.seed);
}

std::uint32_t bits_of(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, 4);
  return b;
}

struct Counts {
  int chunks = 0, refused = 0, frames = 0, models = 0, updates = 0;
};

Counts run_sequence(const std::string& name) {
  std::ifstream txt(vectors_dir() + "/" + name + ".txt", std::ios::binary);
  REQUIRE(txt.good());
  // A sequence without a float file (desktop_cascaded) is checked by the frames' FNV-1a alone.
  std::ifstream f32(vectors_dir() + "/" + name + ".f32", std::ios::binary);
  const std::vector<std::uint8_t> floats((std::istreambuf_iterator<char>(f32)), std::istreambuf_iterator<char>());
  const std::vector<Line> lines = parse_lines(txt);

  Counts counts;
  std::unique_ptr<Decoder> decoder;
  std::optional<protocol::Welcome> welcome;
  std::optional<protocol::SceneUpdate> update;
  std::size_t float_bytes_checked = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& line = lines[i];
    INFO(name << ".txt line " << line.number << " (" << line.kind << ")");
    if (line.kind == "welcome") {
      const Aligned bytes(unhex(line.at("hex")));
      const wire::Message& message = verified(bytes);
      REQUIRE(message.body_type() == wire::Body::Welcome);
      welcome = protocol::read(*message.body_as_Welcome());
      update.reset();
    } else if (line.kind == "stream") {
      // The codec configuration a client derives from the Welcome (CODEC.md 7.1).
      REQUIRE(welcome);
      const StreamConfig c = decoder_config(*welcome);
      CHECK(line.u64("profile_id") == c.profile_id);
      CHECK(line.u64("grid") == c.grid);
      CHECK(line.f64("patch_x_m") == c.patch_x_m);
      CHECK(line.f64("patch_z_m") == c.patch_z_m);
      CHECK(line.f64("gravity_mps2") == c.gravity_mps2);
      CHECK(line.f64("depth_m") == c.depth_m);
      CHECK(line.u64("rate_hz") == c.rate_hz);
      CHECK(line.u64("tick_rate_hz") == c.tick_rate_hz);
      CHECK(bits_of(line.f32("height_step_m")) == bits_of(c.height_step_m));
      CHECK(bits_of(line.f32("slope_step")) == bits_of(c.slope_step));
      CHECK(bits_of(line.f32("disp_step_m")) == bits_of(c.disp_step_m));
      CHECK(line.u64("normals") == (c.normals ? 1u : 0u));
      CHECK(line.u64("choppy") == (c.choppy ? 1u : 0u));
      CHECK((line.fields.count("cascades") ? line.at("cascades") : std::string()) == cascades_text(c.cascades));
      CHECK(line.fields.count("wake") == (c.has_wake() ? 1u : 0u));
      if (c.has_wake())
        CHECK(line.at("wake") == std::to_string(c.wake.grid) + ":" + text_of(c.wake.size_m) + ":" + text_of(c.wake.origin_x_m) +
                                     ":" + text_of(c.wake.origin_z_m) + ":" + text_of(c.wake.decay_per_s) + ":" +
                                     text_of(c.wake.viscosity_m2ps) + ":" + std::to_string(c.wake.epoch_ticks));
      REQUIRE(validate(c).empty());
      DecoderOptions options;
      options.max_payload = line.u64("max_payload");
      options.history_ticks = static_cast<std::uint32_t>(line.u64("history_ticks"));
      options.max_lag = static_cast<std::uint32_t>(line.u64("max_lag"));
      CHECK(options.max_payload == protocol::max_chunk_payload(welcome->max_message_bytes));
      decoder = std::make_unique<Decoder>(c, options);
      if (c.has_wake()) decoder->set_vessels(welcome->vessels);  // Welcome.vessels force the wake (CODEC.md 7.9)
      CHECK(welcome->vessels.empty() == !c.has_wake());
    } else if (line.kind == "scene") {
      REQUIRE(decoder);
      REQUIRE(welcome);
      // The scene of the message just read: the Welcome's from tick 0, a SceneUpdate's from its
      // effective tick; its tag is the serial mod 256.
      const Tick from = update ? update->effective_tick : 0;
      const std::uint32_t serial = update ? update->serial : welcome->scene_serial;
      const protocol::SceneParams& scene = update ? update->scene : welcome->scene;
      check_scene_line(line, from, serial, scene);
      decoder->add_scene(from, static_cast<std::uint8_t>(serial), scene);
    } else if (line.kind == "scene_update") {
      const Aligned bytes(unhex(line.at("hex")));
      const wire::Message& message = verified(bytes);
      REQUIRE(message.body_type() == wire::Body::SceneUpdate);
      update = protocol::read(*message.body_as_SceneUpdate());
      // A new fleet from its effective tick on (CODEC.md 7.9).
      if (update->vessels) decoder->set_vessels(*update->vessels, update->effective_tick);
      ++counts.updates;
    } else if (line.kind == "model") {
      REQUIRE(decoder);
      const Tick tick = line.u64("tick");
      REQUIRE(decoder->scenes().at(tick));
      CHECK(decoder->scenes().at(tick)->tag == line.u64("tag"));
      ModalState state;
      decoder->scenes().model_state(tick, state);
      CHECK(hex64(hash_state(state)) == line.at("state_hash"));
      ++counts.models;
    } else if (line.kind == "chunk") {
      REQUIRE(decoder);
      const std::vector<std::uint8_t> payload = unhex(line.at("payload"));
      const std::vector<std::uint8_t> datagram = unhex(line.at("datagram"));
      // The frames datagram (PROTOCOL.md 3 and 7) carries exactly this record.
      REQUIRE(!datagram.empty());
      REQUIRE(datagram[0] == static_cast<std::uint8_t>(protocol::DatagramKind::frames));
      std::vector<protocol::FrameRecord> records;
      const protocol::FrameBlockResult parsed =
          protocol::decode_frame_block(std::span(datagram).subspan(1), records);
      INFO(parsed.rule);
      REQUIRE(parsed);
      REQUIRE(records.size() == 1);
      const protocol::FrameRecord& r = records[0];
      CHECK(r.tick == line.u64("tick"));
      CHECK(r.baseline == line.u64("baseline"));
      CHECK(r.key == (line.u64("key") == 1));
      CHECK(r.index == line.u64("index"));
      CHECK(r.count == line.u64("count"));
      CHECK(std::vector<std::uint8_t>(r.payload.begin(), r.payload.end()) == payload);
      const ChunkView view{r.tick, r.baseline, r.key, r.index, r.count, r.payload};
      const ChunkError got = decoder->accept(view);
      CHECK(std::string(to_string(got)) == line.at("expect"));
      ++counts.chunks;
      if (line.at("expect") != "ok") ++counts.refused;
    } else if (line.kind == "frame") {
      REQUIRE(decoder);
      const Tick tick = line.u64("tick");
      const ReconstructedFrame* shown = decoder->just_completed();
      REQUIRE(shown);
      CHECK(shown->tick == tick);
      CHECK(shown->complete);
      CHECK(decoder->latest() == shown);  // delivered in order: the newest frame is on show
      REQUIRE(decoder->state(tick));
      CHECK(hex64(hash_state(*decoder->state(tick))) == line.at("state_hash"));
      // Bit-exact floats, channel by channel (frame_channels).
      const auto channels = frame_channels(*shown, decoder->config().choppy);
      if (!decoder->config().choppy) CHECK(line.fields.count("jacobian") == 0);
      const std::size_t size = line.u64("bytes");
      const std::size_t nn = shown->height.size();
      REQUIRE(size == channels.size() * nn * 4);
      std::vector<std::uint8_t> mine;
      for (const auto& [label, channel] : channels) {
        INFO(label);
        REQUIRE(channel->size() == nn);
        for (float v : *channel)
          for (int b = 0; b < 4; ++b) mine.push_back(static_cast<std::uint8_t>(bits_of(v) >> (8 * b)));
      }
      CHECK(hex64(fnv1a64(mine)) == line.at("fnv1a64"));
      if (line.fields.count("offset")) {
        const std::size_t offset = line.u64("offset");
        REQUIRE(offset + size <= floats.size());
        const std::span<const std::uint8_t> expected(floats.data() + offset, size);
        CHECK(hex64(fnv1a64(expected)) == line.at("fnv1a64"));
        CHECK(std::equal(mine.begin(), mine.end(), expected.begin(), expected.end()));
        float_bytes_checked += size;
      }
      // The decimal samples repeat values of the frame's floats.
      const std::vector<std::string> positions = split_commas(line.at("samples"));
      for (const auto& [label, channel] : channels) {
        const std::vector<std::string> values = split_commas(line.at(label));
        REQUIRE(values.size() == positions.size());
        for (std::size_t k = 0; k < positions.size(); ++k)
          CHECK(bits_of(std::strtof(values[k].c_str(), nullptr)) == bits_of(channel->at(std::stoul(positions[k]))));
      }
      // heights,slopes, and for choppy streams the choppy channels' count (informative).
      CHECK(split_commas(line.at("corrections")).size() == (decoder->config().choppy ? 3u : 2u));
      ++counts.frames;
    } else {
      FAIL("unknown line kind " << line.kind);
    }
  }
  CHECK(float_bytes_checked == floats.size());  // every float of the file belongs to a frame line
  return counts;
}

}  // namespace

TEST_CASE("codec vectors: lite_modeled decodes bit for bit (modeled key, corrections, scene change)") {
  const Counts counts = run_sequence("lite_modeled");
  CHECK(counts.frames == 6);
  CHECK(counts.refused == 4);
  CHECK(counts.updates == 1);
  CHECK(counts.models == 2);
}

TEST_CASE("codec vectors: lite_explicit decodes bit for bit (explicit key in several chunks, out of order)") {
  const Counts counts = run_sequence("lite_explicit");
  CHECK(counts.frames == 3);
  CHECK(counts.chunks >= 4);
}

TEST_CASE("codec vectors: mobile_choppy decodes bit for bit (choppy channels, Jacobian, change of choppiness)") {
  const Counts counts = run_sequence("mobile_choppy");
  CHECK(counts.frames == 5);
  CHECK(counts.refused == 3);
  CHECK(counts.updates == 1);
  CHECK(counts.models == 2);
  CHECK(counts.chunks >= 9);  // K+3 comes in several chunks
}

TEST_CASE("codec vectors: mobile_wake decodes bit for bit (codec version 6: a wake lattice, lags 1 and 3)") {
  const Counts counts = run_sequence("mobile_wake");
  CHECK(counts.frames == 5);
  CHECK(counts.refused == 1);
  CHECK(counts.updates == 1);
  CHECK(counts.models == 2);
}

TEST_CASE("codec vectors: desktop_cascaded decodes bit for bit (codec version 5: two lattices)") {
  const Counts counts = run_sequence("desktop_cascaded");
  CHECK(counts.frames == 3);
  CHECK(counts.refused == 1);
  CHECK(counts.updates == 1);
  CHECK(counts.models == 2);
}
