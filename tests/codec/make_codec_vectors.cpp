// Generator of the codec test vectors (CODEC.md section 12): two short streams of the lite profile
// and one of mobile-choppy (codec version 3's choppy channels), written by codec version 4, and one
// of desktop (codec version 5's cascades) and one of mobile with a wake lattice (codec version 6),
// as ocean-server would send them to one client - the
// Welcome, a SceneUpdate, every chunk with its envelope and its frames datagram, a few chunks a
// decoder must refuse, and what a decoder shows once each frame completes. The truth is the scene
// model's own field with a few samples pushed off by 0.6 step, so keys are modeled and frames carry
// height and slope corrections; lite_explicit's truth comes from another seed, so its key falls
// back to explicit coefficients; mobile_choppy's truth also has its displacement and derivatives
// pushed off (and one frame noisy enough to need several chunks), and a SceneUpdate changes only
// the choppiness; desktop_cascaded's pushes fall in both lattices, and its SceneUpdate changes
// the depth.
//
// Runs in memory on every test run (checking that the decoder shows exactly the encoder's
// reconstruction); writes the files only when OCEAN_WRITE_CODEC_VECTORS names a folder:
//   OCEAN_WRITE_CODEC_VECTORS=tests/codec/vectors build/tests/codec/test_codec_vectors "[generate]"
#include "codec_vectors.hpp"

#include "chunk_body.hpp"
#include "decoder.hpp"
#include "encoder.hpp"
#include "frame_records.hpp"
#include "message_builders.hpp"
#include "scene_model.hpp"
#include "state_hash.hpp"
#include "stream_wire.hpp"
#include "wire_limits.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <utility>
#include <vector>

using namespace ocean;
using namespace ocean::codec;
using namespace ocean::codec::vectors;

namespace {

// Ten years of ticks at 30 Hz (beyond 2^33), on the 16-tick key grid of lite under 30 Hz ticks.
constexpr Tick kKeyTick = 9'467'280'000;
constexpr int kTickRateHz = 30;

protocol::SceneParams base_scene() {
  protocol::SceneParams s;
  s.size_x = 64;
  s.size_z = 64;
  s.patch_x_m = 64.0;
  s.patch_z_m = 64.0;
  s.spectrum = model::SpectrumKind::jonswap;
  s.spreading = model::SpreadingKind::donelan_banner;
  s.wind_speed_mps = 8.0;
  s.wind_dir_deg = 30.0;
  s.fetch_m = 100000.0;
  s.amplitude = 1.0;
  s.depth_m = std::numeric_limits<double>::infinity();  // deep water (0 on the wire)
  s.small_wave_m = 0.0;
  s.choppiness = 0.0;
  s.gravity_mps2 = 9.81;
  s.seed = 42;
  return s;
}

// A schedule entry (serial 1): stronger wind from another direction over 12 m of water.
protocol::SceneParams next_scene() {
  protocol::SceneParams s = base_scene();
  s.wind_speed_mps = 11.0;
  s.wind_dir_deg = 75.0;
  s.depth_m = 12.0;
  return s;
}

// mobile_choppy's sea: a JONSWAP storm of 15 m/s at choppiness 1.3 (its Jacobian falls to about 0.43).
protocol::SceneParams choppy_scene() {
  protocol::SceneParams s = base_scene();
  s.spreading = model::SpreadingKind::cos2s;
  s.wind_speed_mps = 15.0;
  s.wind_dir_deg = -20.0;
  s.choppiness = 1.3;
  s.seed = 7;
  return s;
}

protocol::Welcome welcome_of(const protocol::SceneParams& scene, std::uint8_t profile_id = 4,
                             std::vector<std::uint8_t> offered = {1, 4}) {
  const Profile& profile = *find_profile(profile_id);
  protocol::Welcome w;
  w.session_id = 0x1122334455667788ull;
  w.stream = wire_stream(StreamConfig::from_profile(profile, scene.patch_x_m, scene.patch_z_m, scene.gravity_mps2, model::wire_depth(scene.depth_m)));
  w.scene = scene;
  w.offered_profiles = std::move(offered);
  w.epoch_unix_ms = 1'400'000'000'000;
  w.current_tick = kKeyTick - 5;
  w.tick_period_s = 1.0 / kTickRateHz;
  w.max_message_bytes = static_cast<std::uint32_t>(protocol::kDefaultMaxMessageBytes);
  w.scene_serial = 0;
  return w;
}

// What ClientSession gives its decoder (client_session.cpp handle_welcome).
DecoderOptions client_decoder_options(const protocol::Welcome& w) {
  DecoderOptions o;
  o.max_payload = std::max(kDefaultMaxPayload, protocol::max_chunk_payload(w.max_message_bytes));
  o.history_ticks = 32;
  return o;
}

// What ocean-server gives its encoders (profile_stream.cpp stream_encoder_options).
EncoderOptions server_encoder_options() {
  EncoderOptions o;
  o.max_payload = protocol::kMaxChunkPayloadUdp;
  o.history_ticks = protocol::kMaxBaselineGap + 2;
  o.key_history_ticks = protocol::kMaxFrameLag;
  return o;
}

// The scene model's field of `scene` at `tick` (the choppy channels with the scene's choppiness),
// as floats, with `pushed` samples moved off by 0.6 step (heights, displacement) or 0.6 slope step
// (slopes, displacement derivatives), alternating in sign; `noise` pushes more, by its own amounts.
struct Push {
  int channel;  // 0 height, 1 slope_x, 2 slope_z, 3 disp_x, 4 disp_z, 5 disp_xx, 6 disp_zz, 7 disp_xz
  std::uint32_t pos;
};
struct Noise {
  int channel;
  std::uint32_t pos;
  float steps;  // signed, in steps of the channel
};
TruthView model_truth(const StreamConfig& stream, const protocol::SceneParams& scene, Tick tick,
                      const std::vector<Push>& pushed, ReconstructedFrame& storage, const std::vector<Noise>& noise = {}) {
  StreamConfig with_depth = stream;
  with_depth.depth_m = model::wire_depth(scene.depth_m);
  const SceneModel model(with_depth, scene);
  ModalState state;
  model.state_at(tick, state);
  ModalModel modal(with_depth);
  SampleFields fields;
  modal.synthesize(state.cur, stream.choppy ? scene.choppiness : 0.0, fields);
  to_float(fields, stream, storage);
  std::vector<float>* channels[8] = {&storage.height, &storage.slope_x, &storage.slope_z,  &storage.disp_x,
                                     &storage.disp_z, &storage.disp_xx, &storage.disp_zz, &storage.disp_xz};
  const auto step_of = [&](int ch) {
    return ch == 0 ? stream.height_step_m : ch == 3 || ch == 4 ? stream.disp_step_m : stream.slope_step;
  };
  float sign = 1.0f;
  for (const Push& p : pushed) {
    channels[p.channel]->at(p.pos) += sign * 0.6f * step_of(p.channel);
    sign = -sign;
  }
  for (const Noise& p : noise) channels[p.channel]->at(p.pos) += p.steps * step_of(p.channel);
  return TruthView{storage.height, storage.slope_x, storage.slope_z, storage.disp_x, storage.disp_z,
                   storage.disp_xx, storage.disp_zz, storage.disp_xz};
}

std::string scene_fields(const protocol::SceneParams& s) {
  return "size_x=" + std::to_string(s.size_x) + " size_z=" + std::to_string(s.size_z) +
         " patch_x_m=" + text_of(s.patch_x_m) + " patch_z_m=" + text_of(s.patch_z_m) +
         " spectrum=" + std::to_string(static_cast<int>(s.spectrum)) +
         " spreading=" + std::to_string(static_cast<int>(s.spreading)) +
         " wind_speed_mps=" + text_of(s.wind_speed_mps) + " wind_dir_deg=" + text_of(s.wind_dir_deg) +
         " fetch_m=" + text_of(s.fetch_m) + " amplitude=" + text_of(s.amplitude) + " depth_m=" + text_of(model::wire_depth(s.depth_m)) +
         " small_wave_m=" + text_of(s.small_wave_m) + " choppiness=" + text_of(s.choppiness) +
         " gravity_mps2=" + text_of(s.gravity_mps2) + " seed=" + std::to_string(s.seed);
}

// One sequence being written: the text lines, the float file, and a decoder fed exactly what the
// lines say (its results are what the lines expect).
class Writer {
 public:
  // Without a float file, frame lines carry no offset: their floats are checked by FNV-1a alone.
  Writer(std::string name, std::string title, int codec_version = 4, bool float_file = true)
      : name_(std::move(name)), float_file_(float_file) {
    text_ << "# " << name_ << ": " << title << "\n"
          << "# Codec version " << codec_version
          << " / protocol version 3 test vectors; the format is in protocol/codec/CODEC.md section 12.\n"
          << "# Generated by tests/codec/make_codec_vectors.cpp, checked by tests/codec/test_codec_vectors.cpp.\n";
  }

  void comment(const std::string& text) { text_ << "# " << text << "\n"; }

  Decoder& welcome(const protocol::Welcome& w) {
    const protocol::Bytes bytes = protocol::encode(w);
    text_ << "welcome hex=" << hex(bytes) << "\n";
    const StreamConfig c = decoder_config(w);
    text_ << "stream profile_id=" << int(c.profile_id) << " grid=" << c.grid << " patch_x_m=" << text_of(c.patch_x_m)
          << " patch_z_m=" << text_of(c.patch_z_m) << " gravity_mps2=" << text_of(c.gravity_mps2)
          << " depth_m=" << text_of(c.depth_m) << " rate_hz=" << c.rate_hz << " tick_rate_hz=" << c.tick_rate_hz
          << " height_step_m=" << text_of(c.height_step_m) << " slope_step=" << text_of(c.slope_step)
          << " disp_step_m=" << text_of(c.disp_step_m) << " normals=" << int(c.normals) << " choppy=" << int(c.choppy)
          << " max_payload=" << client_decoder_options(w).max_payload << " history_ticks=32 max_lag=1024";
    if (!c.cascades.empty()) text_ << " cascades=" << cascades_text(c.cascades);
    if (c.has_wake())
      text_ << " wake=" << c.wake.grid << ":" << text_of(c.wake.size_m) << ":" << text_of(c.wake.origin_x_m) << ":"
            << text_of(c.wake.origin_z_m) << ":" << text_of(c.wake.decay_per_s) << ":" << text_of(c.wake.viscosity_m2ps)
            << ":" << c.wake.epoch_ticks;
    text_ << "\n";
    text_ << "scene from=0 serial=" << w.scene_serial << " tag=" << (w.scene_serial % 256) << " " << scene_fields(w.scene)
          << "\n";
    decoder_ = std::make_unique<Decoder>(c, client_decoder_options(w));
    if (c.has_wake()) decoder_->set_vessels(w.vessels);
    decoder_->add_scene(0, static_cast<std::uint8_t>(w.scene_serial), w.scene);
    config_ = c;
    positions_.assign(std::begin(kSamplePositions), std::end(kSamplePositions));
    const std::vector<StreamConfig::Lattice> lattices = c.lattices();
    for (std::size_t l = 1; l < lattices.size(); ++l) {
      const auto at = static_cast<std::uint32_t>(lattices[l].samples_at);
      const auto nn = static_cast<std::uint32_t>(lattices[l].n * lattices[l].n);
      positions_.insert(positions_.end(), {at, at + 517, at + nn - 1});
    }
    return *decoder_;
  }

  void scene_update(const protocol::SceneUpdate& u) {
    text_ << "scene_update hex=" << hex(protocol::encode(u)) << "\n";
    text_ << "scene from=" << u.effective_tick << " serial=" << u.serial << " tag=" << (u.serial % 256) << " "
          << scene_fields(u.scene) << "\n";
    decoder_->add_scene(u.effective_tick, static_cast<std::uint8_t>(u.serial), u.scene);
    if (u.vessels) decoder_->set_vessels(*u.vessels, u.effective_tick);
  }

  // The scene model's state of `tick` (before any correction), for checking a scene model alone.
  void model(Tick tick) {
    ModalState s;
    decoder_->scenes().model_state(tick, s);
    text_ << "model tick=" << tick << " tag=" << int(decoder_->scenes().at(tick)->tag) << " state_hash=" << hex64(hash_state(s))
          << "\n";
  }

  void chunk(const Chunk& c, const std::string& what, ChunkError expect = ChunkError::ok) {
    const protocol::FrameRecord record{c.tick, c.baseline, c.key, c.index, c.count, c.payload};
    const protocol::Bytes datagram = protocol::frames_datagram(std::span(&record, 1));
    text_ << "chunk what=" << what << " tick=" << c.tick << " baseline=" << c.baseline << " key=" << int(c.key)
          << " index=" << c.index << " count=" << c.count << " payload=" << hex(c.payload)
          << " datagram=" << hex(datagram) << " expect=" << to_string(expect) << "\n";
    const ChunkError got = decoder_->accept(c);
    INFO(name_ << ": chunk " << what << " of tick " << c.tick);
    REQUIRE(to_string(got) == to_string(expect));
  }

  // After the chunk that completed `frame`: what the decoder shows, which must be the encoder's own
  // reconstruction bit for bit.
  void frame(const EncodedFrame& frame) {
    const ReconstructedFrame* shown = decoder_->just_completed();
    INFO(name_ << ": frame " << frame.id.tick);
    REQUIRE(shown);
    REQUIRE(shown->tick == frame.id.tick);
    REQUIRE(shown->complete);
    REQUIRE(shown->height == frame.reconstruction.height);
    REQUIRE(shown->slope_x == frame.reconstruction.slope_x);
    REQUIRE(shown->slope_z == frame.reconstruction.slope_z);
    REQUIRE(shown->disp_x == frame.reconstruction.disp_x);
    REQUIRE(shown->disp_z == frame.reconstruction.disp_z);
    REQUIRE(shown->disp_xx == frame.reconstruction.disp_xx);
    REQUIRE(shown->disp_zz == frame.reconstruction.disp_zz);
    REQUIRE(shown->disp_xz == frame.reconstruction.disp_xz);
    REQUIRE(shown->jacobian == frame.reconstruction.jacobian);
    const auto channels = frame_channels(*shown, config_.choppy);
    const std::size_t offset = floats_.size();
    for (const auto& [label, channel] : channels)
      for (float v : *channel) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        for (int b = 0; b < 4; ++b) floats_.push_back(static_cast<std::uint8_t>(bits >> (8 * b)));
      }
    const std::span<const std::uint8_t> bytes(floats_.data() + offset, floats_.size() - offset);
    text_ << "frame tick=" << shown->tick << " complete=1";
    if (float_file_) text_ << " offset=" << offset;
    text_ << " bytes=" << bytes.size()
          << " fnv1a64=" << hex64(fnv1a64(bytes)) << " state_hash=" << hex64(hash_state(*decoder_->state(shown->tick)))
          << " corrections=" << frame.stats.corrections_height << "," << frame.stats.corrections_slope;
    if (config_.choppy) text_ << "," << frame.stats.corrections_choppy;
    auto samples = [&](const char* label, const std::vector<float>& v) {
      text_ << " " << label << "=";
      bool first = true;
      for (std::uint32_t p : positions_) {
        text_ << (first ? "" : ",") << text_of(v.at(p));
        first = false;
      }
    };
    text_ << " samples=";
    bool first = true;
    for (std::uint32_t p : positions_) {
      text_ << (first ? "" : ",") << p;
      first = false;
    }
    for (const auto& [label, channel] : channels) samples(label, *channel);
    text_ << "\n";
    if (!float_file_) floats_.clear();
  }

  // A frame whose chunks all arrive in order.
  void frame_in_order(const EncodedFrame& f, const std::string& what) {
    for (const Chunk& c : f.chunks) chunk(c, what);
    frame(f);
  }

  const StreamConfig& config() const { return config_; }

  void write(const std::string& dir) const {
    std::ofstream txt(dir + "/" + name_ + ".txt", std::ios::binary);
    txt << text_.str();
    REQUIRE(txt.good());
    if (!float_file_) return;
    std::ofstream f32(dir + "/" + name_ + ".f32", std::ios::binary);
    f32.write(reinterpret_cast<const char*>(floats_.data()), static_cast<std::streamsize>(floats_.size()));
    REQUIRE(f32.good());
  }

 private:
  std::string name_;
  bool float_file_;
  std::vector<std::uint32_t> positions_;
  std::ostringstream text_;
  std::vector<std::uint8_t> floats_;
  std::unique_ptr<Decoder> decoder_;
  StreamConfig config_;
};

// A copy of `c` whose header (and so its CRC) is edited; the body is kept.
Chunk rebuilt(const Chunk& c, int grid_log2, const std::function<void(ChunkHeader&)>& edit) {
  ChunkHeader h;
  std::span<const std::uint8_t> body;
  REQUIRE(parse_payload(view(c), 65536, grid_log2, h, body) == ChunkError::ok);
  edit(h);
  Chunk out = c;
  out.payload = write_payload(h, view(c), grid_log2, body);
  return out;
}

void lite_modeled(Writer& w) {
  const protocol::SceneParams scene0 = base_scene(), scene1 = next_scene();
  const protocol::Welcome welcome = welcome_of(scene0);
  w.comment("The lite profile (32 x 32, 15 Hz, slopes) under 30 Hz server ticks: frames on even ticks.");
  w.comment("K = " + std::to_string(kKeyTick) + " (ten years of 30 Hz ticks), the key tick.");
  w.comment("Scene 0 from the Welcome; scene 1 (wind, direction and depth change) from tick " +
            std::to_string(kKeyTick + 9) + " by a SceneUpdate.");
  Decoder& dec = w.welcome(welcome);
  (void)dec;
  const StreamConfig& c = w.config();
  const Tick change = kKeyTick + 9;
  Encoder enc(c, server_encoder_options());
  enc.set_scene(0, 0, scene0);
  enc.set_scene(change, 1, scene1);
  const protocol::SceneUpdate update{0, change, scene1, 1};

  ReconstructedFrame truth;
  auto feed = [&](Tick tick, const std::vector<Push>& pushed) {
    enc.add_truth(tick, model_truth(c, tick < change ? scene0 : scene1, tick, pushed, truth));
  };
  for (Tick t = kKeyTick - 1; t <= kKeyTick + 12; ++t) {
    std::vector<Push> pushed;
    if (t == kKeyTick) pushed = {{0, 40}, {0, 300}, {0, 301}, {0, 1000}, {1, 77}, {1, 500}, {2, 600}, {2, 5}};
    if (t == kKeyTick + 4) pushed = {{0, 123}, {0, 900}, {1, 64}, {2, 1023}};
    if (t == kKeyTick + 10) pushed = {{0, 517}, {2, 200}};
    feed(t, pushed);
  }

  w.comment("The key: the scene model's state of its tick; its truth has 4 heights and 4 slopes pushed off.");
  w.model(kKeyTick);
  const auto key = enc.encode_key(kKeyTick);
  REQUIRE(key->chunks.size() == 1);
  w.frame_in_order(*key, "modeled_key");
  w.chunk(key->chunks[0], "again", ChunkError::duplicate_chunk);

  w.comment("Deltas K+2 from K and K+4 from K (whose truth has 2 heights and 2 slopes pushed off). A height");
  w.comment("correction folded into the state moves the next frames' slopes a little (the truth has no such");
  w.comment("bump), so later frames carry some slope corrections too: `corrections` counts heights,slopes.");
  const auto d2 = enc.encode_delta(kKeyTick + 2, key->id);
  w.frame_in_order(*d2, "delta");
  const auto d4 = enc.encode_delta(kKeyTick + 4, key->id);
  w.frame_in_order(*d4, "delta");

  w.comment("The SceneUpdate of scene 1 (sent a lead ahead of its effective tick).");
  w.scene_update(update);
  w.model(change);

  const auto d6 = enc.encode_delta(kKeyTick + 6, d4->id);
  w.comment("Refused: K+6 with its scene tag byte changed (the CRC covers it), then re-signed with tag 1.");
  Chunk bad = d6->chunks[0];
  bad.payload.at(3) ^= 1;
  w.chunk(bad, "corrupted", ChunkError::checksum_mismatch);
  w.chunk(rebuilt(d6->chunks[0], c.grid_log2(), [](ChunkHeader& h) { h.scene_tag = 1; }), "wrong_tag",
          ChunkError::unknown_scene);
  w.frame_in_order(*d6, "delta");

  w.comment("K+10 from K+4 crosses the change at K+9: the state becomes scene 1's model state at K+9,");
  w.comment("then advances one tick with scene 1's recurrence (depth 12 m); its truth has 1 height, 1 slope pushed off.");
  const auto d10 = enc.encode_delta(kKeyTick + 10, d4->id);
  w.frame_in_order(*d10, "delta");
  const auto d12 = enc.encode_delta(kKeyTick + 12, d10->id);
  w.frame_in_order(*d12, "delta");

  w.comment("Refused: a delta of K+14 from K+8, a tick this client never completed.");
  Chunk orphan;
  orphan.tick = kKeyTick + 14;
  orphan.baseline = kKeyTick + 8;
  orphan.key = false;
  orphan.index = 0;
  orphan.count = 1;
  ChunkHeader h;
  h.normals = true;
  h.whole = true;
  h.scene_tag = 1;
  const BodyLayout layout{0, 32u * 32u, true};
  orphan.payload = write_payload(h, view(orphan), c.grid_log2(), encode_body(layout, 0, layout.total(), {}, Corrections{}));
  w.chunk(orphan, "orphan", ChunkError::unknown_baseline);
}

void lite_explicit(Writer& w) {
  const protocol::SceneParams scene0 = base_scene();
  protocol::SceneParams other = scene0;
  other.seed = 43;  // the truth is another sea than the one announced: the scene model misses it
  const protocol::Welcome welcome = welcome_of(scene0);
  const StreamConfig c = decoder_config(welcome);
  Encoder enc(c, server_encoder_options());
  enc.set_scene(0, 0, scene0);
  ReconstructedFrame truth;
  for (Tick t = kKeyTick - 1; t <= kKeyTick + 4; ++t) enc.add_truth(t, model_truth(c, other, t, {}, truth));
  const auto key = enc.encode_key(kKeyTick);
  REQUIRE(key->chunks.size() >= 2);
  w.comment("The stream of lite_modeled, but the truth is the scene model of seed 43 while the scene says 42:");
  w.comment("the modeled key would need nearly every sample corrected, so the key is explicit (codec 1");
  w.comment("coefficients, from the truth at K and K-1) in " + std::to_string(key->chunks.size()) +
            " chunks, delivered last first. K = " + std::to_string(kKeyTick) + ".");
  w.welcome(welcome);
  for (auto it = key->chunks.rbegin(); it != key->chunks.rend(); ++it) w.chunk(*it, "explicit_key");
  w.frame(*key);
  w.comment("Deltas from the explicit key: K+2 from K, K+4 from K+2.");
  const auto d2 = enc.encode_delta(kKeyTick + 2, key->id);
  w.frame_in_order(*d2, "delta");
  const auto d4 = enc.encode_delta(kKeyTick + 4, d2->id);
  w.frame_in_order(*d4, "delta");
}

void mobile_choppy(Writer& w) {
  const protocol::SceneParams scene0 = choppy_scene();
  protocol::SceneParams scene1 = scene0;
  scene1.choppiness = 0.6;  // the only change: same heights, other choppy factors G_j
  const protocol::Welcome welcome = welcome_of(scene0, 5, {1, 5});
  const Tick change = kKeyTick + 5;
  w.comment("The mobile-choppy profile (profile 5: 64 x 64, 30 Hz, slopes, choppy channels) under 30 Hz server");
  w.comment("ticks: a frame every tick. K = " + std::to_string(kKeyTick) + ", the key tick. Scene 0 (JONSWAP, cos-2s,");
  w.comment("15 m/s towards -20 deg, choppiness 1.3) from the Welcome; scene 1, the same but choppiness 0.6,");
  w.comment("from tick " + std::to_string(change) + " by a SceneUpdate. Each frame's floats are height, slope_x,");
  w.comment("slope_z, disp_x, disp_z, disp_xx, disp_zz, disp_xz and jacobian; `corrections` counts");
  w.comment("heights,slopes,choppy channels.");
  w.welcome(welcome);
  const StreamConfig& c = w.config();
  REQUIRE(c.choppy);
  REQUIRE(c.grid == 64);
  Encoder enc(c, server_encoder_options());
  enc.set_scene(0, 0, scene0);
  enc.set_scene(change, 1, scene1);
  const protocol::SceneUpdate update{0, change, scene1, 1};

  // K+3's truth is noisy in disp_x and disp_xz (about half the samples each, 0.6 to 7.4 steps):
  // too many corrections for one 1104-byte chunk. std::mt19937's raw output is the same everywhere.
  std::vector<Noise> noise;
  std::mt19937 rng(2026);
  constexpr float kMagnitudes[] = {0.6f, 1.3f, 2.9f, 7.4f};
  for (int ch : {3, 7})
    for (std::uint32_t pos = 0; pos < 64u * 64u; ++pos) {
      const std::uint32_t r = rng();
      if (r & 1u) continue;
      noise.push_back({ch, pos, (r & 2u ? -1.0f : 1.0f) * kMagnitudes[(r >> 2) & 3u]});
    }
  ReconstructedFrame truth;
  for (Tick t = kKeyTick - 1; t <= kKeyTick + 6; ++t) {
    std::vector<Push> pushed;
    if (t == kKeyTick)
      pushed = {{0, 100}, {0, 2000}, {1, 300}, {2, 3000}, {3, 41}, {4, 1234}, {5, 2222}, {6, 3333}, {7, 4000}, {7, 517}};
    if (t == kKeyTick + 2) pushed = {{0, 700}, {4, 701}, {5, 9}};
    if (t == kKeyTick + 6) pushed = {{6, 1500}, {3, 4095}};
    enc.add_truth(t, model_truth(c, t < change ? scene0 : scene1, t, pushed, truth,
                                 t == kKeyTick + 3 ? noise : std::vector<Noise>{}));
  }

  w.comment("The key: the scene model's state of its tick; its truth has 2 heights, 2 slopes and 6 samples");
  w.comment("of the choppy channels (one or two in each) pushed off.");
  w.model(kKeyTick);
  const auto key = enc.encode_key(kKeyTick);
  REQUIRE(key->chunks.size() == 1);
  REQUIRE(key->stats.corrections_choppy >= 6);
  w.comment("Refused first: the key re-signed with flag bit 4 (choppy) clear, the key re-signed with flag");
  w.comment("bit 7 (wake, codec version 6) set, and the key with flag bit 5 (binary32 synthesis) clear, as");
  w.comment("version 3 would send it (the flags are read before the CRC, so it need not be re-signed).");
  w.chunk(rebuilt(key->chunks[0], c.grid_log2(), [](ChunkHeader& h) { h.choppy = false; }), "not_choppy",
          ChunkError::wrong_dimensions);
  w.chunk(rebuilt(key->chunks[0], c.grid_log2(), [](ChunkHeader& h) { h.wake = true; }), "wake_flag",
          ChunkError::wrong_dimensions);
  Chunk version3 = key->chunks[0];
  version3.payload.at(0) &= static_cast<std::uint8_t>(~0x20u);
  w.chunk(version3, "version_3", ChunkError::unknown_version);
  w.frame_in_order(*key, "modeled_key");

  w.comment("Delta K+2 from K (its truth has a height, disp_z and disp_xx pushed off; the key's height");
  w.comment("corrections, folded into its state, also bump the slopes and choppy channels a little), then");
  w.comment("K+3 from K+2, whose truth is noisy in disp_x and disp_xz: its chunks (item ranges) arrive last first.");
  const auto d2 = enc.encode_delta(kKeyTick + 2, key->id);
  w.frame_in_order(*d2, "delta");
  const auto d3 = enc.encode_delta(kKeyTick + 3, d2->id);
  REQUIRE(d3->chunks.size() >= 2);
  for (auto it = d3->chunks.rbegin(); it != d3->chunks.rend(); ++it) w.chunk(*it, "delta");
  w.frame(*d3);

  w.comment("The SceneUpdate of scene 1: only the choppiness changes (1.3 to 0.6), at K+5.");
  w.scene_update(update);
  w.model(change);
  w.comment("K+5 from K+3: the frame of the effective tick, scene 1's model state with the G_j of 0.6;");
  w.comment("then K+6 from K+5 (its truth has disp_zz and disp_x pushed off).");
  const auto d5 = enc.encode_delta(kKeyTick + 5, d3->id);
  w.frame_in_order(*d5, "delta");
  const auto d6 = enc.encode_delta(kKeyTick + 6, d5->id);
  w.frame_in_order(*d6, "delta");
}

void desktop_cascaded(Writer& w) {
  protocol::SceneParams scene = base_scene();
  scene.size_x = scene.size_z = 256;
  scene.patch_x_m = scene.patch_z_m = 256.0;
  scene.spreading = model::SpreadingKind::hasselmann;
  scene.wind_speed_mps = 14.0;
  scene.wind_dir_deg = 120.0;
  scene.seed = 11;
  const protocol::Welcome welcome = welcome_of(scene, 2, {1, 2});
  w.comment("The desktop profile (profile 2: slopes, 30 Hz) under 30 Hz server ticks: a cascaded stream");
  w.comment("(codec version 5) of two lattices, a 256 x 256 tile of the waves from 8 cycles per 256 m up and");
  w.comment("a 128 x 128 cascade over 2048 m of those below 64 cycles per 2048 m. Samples 0..65535 are the");
  w.comment("tile's, 65536..81919 the cascade's. K = " + std::to_string(kKeyTick) + ", the key tick. Scene 0:");
  w.comment("JONSWAP, Hasselmann, 14 m/s towards 120 deg, deep, seed 11 (the cascade draws with seed");
  w.comment("11 XOR 0x9E3779B97F4A7C15); scene 1 from K+2 by a SceneUpdate. No .f32 file: frame lines have");
  w.comment("no offset, and a checker compares the FNV-1a of its own floats.");
  w.welcome(welcome);
  const StreamConfig& c = w.config();
  REQUIRE(c.cascades.size() == 2);
  REQUIRE(c.samples() == 256u * 256 + 128u * 128);
  // Scene 1: the wind veers and freshens over 30 m of water (both lattices' dispersion and TMA change).
  protocol::SceneParams scene1 = scene;
  scene1.wind_speed_mps = 16.0;
  scene1.wind_dir_deg = 100.0;
  scene1.depth_m = 30.0;
  const Tick change = kKeyTick + 2;
  const protocol::SceneUpdate update{0, change, scene1, 1};
  Encoder enc(c, server_encoder_options());
  enc.set_scene(0, 0, scene);
  enc.set_scene(change, 1, scene1);
  constexpr std::uint32_t kCoarse = 256u * 256;  // the cascade's first sample
  ReconstructedFrame truth;
  for (Tick t = kKeyTick - 1; t <= kKeyTick + 3; ++t) {
    std::vector<Push> pushed;
    if (t == kKeyTick)
      pushed = {{0, 100}, {0, 40000}, {0, kCoarse + 77}, {0, kCoarse + 16000}, {1, 5000}, {2, kCoarse + 900}};
    if (t == kKeyTick + 1) pushed = {{0, kCoarse + 4321}, {1, 123}};
    if (t == kKeyTick + 3) pushed = {{0, 65535}, {0, kCoarse}, {2, kCoarse + 16383}};
    enc.add_truth(t, model_truth(c, t < change ? scene : scene1, t, pushed, truth));
  }

  w.comment("The key: the scene model's state of its tick, both lattices; its truth has 2 heights and a slope");
  w.comment("of the tile and 2 heights and a slope of the cascade pushed off.");
  w.model(kKeyTick);
  const auto key = enc.encode_key(kKeyTick);
  REQUIRE(key->chunks.size() == 1);
  w.comment("Refused first: the key re-signed with flag bit 6 (cascaded) clear, as a stream without cascades");
  w.comment("would send it.");
  w.chunk(rebuilt(key->chunks[0], c.grid_log2(), [](ChunkHeader& h) { h.cascaded = false; }), "not_cascaded",
          ChunkError::wrong_dimensions);
  w.frame_in_order(*key, "modeled_key");
  w.comment("Delta K+1 from K (its truth has a height of the cascade and a slope of the tile pushed off).");
  const auto d1 = enc.encode_delta(kKeyTick + 1, key->id);
  w.frame_in_order(*d1, "delta");

  w.comment("The SceneUpdate of scene 1 (16 m/s towards 100 deg over 30 m of water), effective at K+2.");
  w.scene_update(update);
  w.model(change);
  w.comment("K+3 from K+1 crosses the change: the state becomes scene 1's model state at K+2 (each lattice");
  w.comment("its cascade's), then advances one tick with the 30 m recurrence; its truth has the tile's last");
  w.comment("height, the cascade's first height and the cascade's last slope_z pushed off.");
  const auto d3 = enc.encode_delta(kKeyTick + 3, d1->id);
  w.frame_in_order(*d3, "delta");
}

// A hollow 0.25 m deep, 12 m wide, moving 3 m a tick along x through the wake lattice (the truth
// of a wake need not be a sim's: any field is corrected), heights and exact slopes added to the
// lattice's samples of `storage`.
void add_moving_hollow(const StreamConfig& c, Tick tick, ReconstructedFrame& storage) {
  const StreamConfig::Lattice wake = c.lattices().back();
  REQUIRE(wake.wake);
  const double spacing = wake.patch_x_m / wake.n, sigma = 12.0, depth = 0.25;
  const double cx = 60.0 + 3.0 * static_cast<double>(tick - kKeyTick), cz = 128.0;
  for (int j = 0; j < wake.n; ++j)
    for (int i = 0; i < wake.n; ++i) {
      const double x = i * spacing - cx, z = j * spacing - cz;
      const double h = -depth * std::exp(-(x * x + z * z) / (2 * sigma * sigma));
      const std::size_t at = wake.samples_at + static_cast<std::size_t>(j) * wake.n + i;
      storage.height.at(at) += static_cast<float>(h);
      storage.slope_x.at(at) += static_cast<float>(-h * x / (sigma * sigma));
      storage.slope_z.at(at) += static_cast<float>(-h * z / (sigma * sigma));
    }
}

void mobile_wake(Writer& w) {
  protocol::SceneParams scene = base_scene();
  scene.size_x = scene.size_z = 64;
  protocol::Welcome welcome = welcome_of(scene, 1, {1, 4});
  welcome.stream.wake = WakeLattice{32, 256.0, -128.0, -128.0, 0.5, 1e-3, 3};
  // One vessel, 20 x 5 m with 1.2 m draft, waiting at (-80, 10) until 10 s before K, then sailing
  // east at 6 m/s through the lattice's middle; one moored (a single waypoint), heading +x.
  const double k_s = static_cast<double>(kKeyTick) / kTickRateHz;
  model::VesselTrack sailing;
  sailing.id = 1;
  sailing.hull = {20.0, 5.0, 1.2};
  sailing.points = {{0.0, -80.0, 10.0}, {k_s - 10.0, -80.0, 10.0}, {k_s + 90.0, 520.0, 10.0}};
  model::VesselTrack moored;
  moored.id = 2;
  moored.hull = {12.0, 4.0, 0.8};
  moored.points = {{0.0, 40.0, -30.0}};
  // Removed between K+3 and K+4: present from time 0 until K/30 + 0.14 s (tick K+4's step is at
  // K/30 + 0.15 s).
  moored.presence = {0.0, k_s + 0.14, 0.0};
  // A dropped object (codec version 7): a round hull 3 m across pressing 1.5 m, at (0, 40), for
  // 0.1 s every 0.2 s from K/30 - so present for the steps of K..K+2 and K+6..K+7, absent for K-3..K-1
  // (u < 0, taken modulo) and K+3..K+5.
  model::VesselTrack dropped;
  dropped.id = 3;
  dropped.hull = {3.0, 3.0, 1.5};
  dropped.points = {{0.0, 0.0, 40.0}};
  dropped.presence = {k_s, 0.1, 0.2};
  welcome.vessels = {sailing, moored, dropped};
  w.comment("The mobile profile (profile 1: grid 64, slopes, 30 Hz) under 30 Hz server ticks, with a wake");
  w.comment("lattice (codec version 6, CODEC.md 7.9): 32 x 32 samples over 256 m, decay 0.5/s, viscosity");
  w.comment("1e-3 m^2/s (strong, so the damped recurrence shows within a few ticks), epochs of 3 ticks (K is");
  w.comment("one's first tick: the key holds the wake of epochs K/3 - 1 and K/3; K+4 from K+1 crosses K+3, where");
  w.comment("epoch K/3 - 1's wake is dropped, and K+6 from K+4 crosses K+6). Samples 0..4095 are the");
  w.comment("sea's, 4096..5119 the wake's. K = " + std::to_string(kKeyTick) + ". Scene 0 as lite_modeled's, at");
  w.comment("grid 64; scene 1 from K+5 by a SceneUpdate: 20 m of water (the wake rides through the change).");
  w.comment("The wake's truth: a hollow 0.25 m deep, 12 m wide, moving 3 m a tick along the lattice. No .f32 file.");
  w.comment("Welcome.vessels: vessel 1 (20 x 5 m, draft 1.2) waits at (-80, 10) until K/30 - 10 s, then sails");
  w.comment("east at 6 m/s along z = 10; vessel 2 (12 x 4 m, draft 0.8) is moored at (40, -30): their");
  w.comment("pressure forces every advance of the wake's modes (CODEC.md 7.9), and the hollow is corrected.");
  w.comment("Presence (codec version 7, protocol version 3): vessel 2 is removed from K/30 + 0.14 s; object 3");
  w.comment("(3 m round, 1.5 m) at (0, 40) presses for 0.1 s every 0.2 s from K/30: during the steps of ticks");
  w.comment("K..K+2 and K+6..K+7, not K-3..K-1 (its fmod is negative there) nor K+3..K+5. The SceneUpdate");
  w.comment("at K+5 carries the fleet from K+5 on (SceneUpdate.vessels): the Welcome's and a launch sailing");
  w.comment("north from (-40, -40) from K+5; a decoder replaces its fleet with it.");
  w.welcome(welcome);
  const StreamConfig& c = w.config();
  REQUIRE(c.has_wake());
  REQUIRE(c.samples() == 64u * 64 + 32u * 32);
  protocol::SceneParams scene1 = scene;
  scene1.depth_m = 20.0;
  const Tick change = kKeyTick + 5;
  // The SceneUpdate also brings a new fleet (protocol version 3, a vessel command): a launch put in
  // at (-40, -40) from K+5, sailing north at 5 m/s; the Welcome's tracks are unchanged before it.
  protocol::SceneUpdate update{0, change, scene1, 1};
  model::VesselTrack launch;
  launch.id = 4;
  launch.hull = {8.0, 3.0, 0.6};
  const double change_s = static_cast<double>(change) / kTickRateHz;
  launch.points = {{0.0, -40.0, -40.0}, {change_s, -40.0, -40.0}, {change_s + 20.0, -40.0, 60.0}};
  launch.presence = {change_s, std::numeric_limits<double>::infinity(), 0.0};
  update.vessels = welcome.vessels;
  update.vessels->push_back(launch);
  Encoder enc(c, server_encoder_options());
  enc.set_scene(0, 0, scene);
  enc.set_scene(change, 1, scene1);
  enc.set_vessels(welcome.vessels);
  enc.set_vessels(*update.vessels, change);
  ReconstructedFrame truth;
  for (Tick t = kKeyTick - 1; t <= kKeyTick + 7; ++t) {
    std::vector<Push> pushed;
    if (t == kKeyTick) pushed = {{0, 100}, {1, 2000}};
    model_truth(c, t < change ? scene : scene1, t, pushed, truth);
    add_moving_hollow(c, t, truth);
    enc.add_truth(t, TruthView{truth.height, truth.slope_x, truth.slope_z, truth.disp_x, truth.disp_z, truth.disp_xx,
                               truth.disp_zz, truth.disp_xz});
  }
  w.comment("The key: the scene model's state (the wake's modes 0); the hollow comes as corrections, which a");
  w.comment("key folds into both X(t-1) and X(t) of every lattice.");
  w.model(kKeyTick);
  const auto key = enc.encode_key(kKeyTick);
  w.comment("Refused first: the key re-signed with flag bit 7 (wake) clear, as a stream without a wake would send it.");
  w.chunk(rebuilt(key->chunks[0], c.grid_log2(), [](ChunkHeader& h) { h.wake = false; }), "not_wake",
          ChunkError::wrong_dimensions);
  w.frame_in_order(*key, "modeled_key");
  w.comment("K+1 from K (lag 1: the wake's corrections go into X(t) only), K+4 from K+1 (lag 3: X(t-1) takes");
  w.comment("D - D/3), K+6 from K+4 across the change at K+5 (the sea's lattice takes scene 1's model state at");
  w.comment("K+5; the wake's modes advance to K+5 with scene 0's damped recurrence, then to K+6 with scene 1's),");
  w.comment("K+7 from K+6.");
  const auto d1 = enc.encode_delta(kKeyTick + 1, key->id);
  w.frame_in_order(*d1, "delta");
  const auto d4 = enc.encode_delta(kKeyTick + 4, d1->id);
  w.frame_in_order(*d4, "delta");
  w.scene_update(update);
  w.model(change);
  const auto d6 = enc.encode_delta(kKeyTick + 6, d4->id);
  w.frame_in_order(*d6, "delta");
  const auto d7 = enc.encode_delta(kKeyTick + 7, d6->id);
  w.frame_in_order(*d7, "delta");
}

}  // namespace

TEST_CASE("codec vectors: the generator's streams decode to the encoder's reconstructions", "[generate]") {
  Writer modeled("lite_modeled", "a modeled key, deltas with corrections, a scene change, refusals");
  lite_modeled(modeled);
  Writer explicit_key("lite_explicit", "an explicit (coefficient) key in several chunks, then deltas");
  lite_explicit(explicit_key);
  Writer choppy("mobile_choppy", "a choppy stream (codec version 4): a modeled key, deltas with choppy corrections, a change of choppiness");
  mobile_choppy(choppy);
  Writer cascaded("desktop_cascaded", "a cascaded stream (codec version 5): a modeled key with corrections in both lattices, deltas, a change of depth", 5,
                  false);
  desktop_cascaded(cascaded);
  Writer wake("mobile_wake", "a stream with a wake lattice (codec version 7): a modeled key, deltas at lags 1 and 3, a change of depth, hulls present at times", 7,
              false);
  mobile_wake(wake);
  if (const char* dir = std::getenv("OCEAN_WRITE_CODEC_VECTORS"); dir && *dir) {
    modeled.write(dir);
    explicit_key.write(dir);
    choppy.write(dir);
    cascaded.write(dir);
    wake.write(dir);
    WARN("codec vectors written to " << dir);
  }
}
