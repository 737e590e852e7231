// ocean-bench codec: bitrate, error and per-frame cost of the height/normal stream codec against
// simple baselines (raw floats, quantized + zstd, quantized deltas + zstd), all on the same frames
// of the real sim (default scene, the profile's grid via evaluate_band at t = tick / rate_hz).
#include "bench.hpp"

#include "decoder.hpp"
#include "encoder.hpp"
#include "frame_records.hpp"
#include "profile_stream.hpp"
#include "stream_wire.hpp"
#include "cascade_set.hpp"
#include "ocean.hpp"
#include "profile.hpp"
#include "config_loader.hpp"
#include "epoch_wake.hpp"
#include "frame_producer.hpp"

#include <CLI/CLI.hpp>
#include <zstd.h>

#include "common/json_writer.hpp"
#include "common/worker_pool.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace ocean;
namespace model = ocean::model;
using codec::Chunk;
using codec::StreamConfig;

// Error and timing accumulated by every method.
struct Tally {
  std::string method;
  int lag = 0;
  int decode_threads = 0;  // ours: threads per decoder
  double bytes = 0;          // steady-state bytes counted for kbps (payload + envelope)
  double frames = 0;
  double max_err = 0, sum_sq = 0, count = 0, max_slope_err = 0;
  std::vector<double> enc_us, dec_us;
  void error(const sim::Frame& truth, const std::vector<float>& h, const std::vector<float>* sx,
             const std::vector<float>* sz) {
    for (std::size_t i = 0; i < h.size(); ++i) {
      const double e = std::fabs(double(truth.height[i]) - double(h[i]));
      max_err = std::max(max_err, e);
      sum_sq += e * e;
      count += 1;
      if (sx) {
        max_slope_err = std::max(max_slope_err, std::fabs(double(truth.slope_x[i]) - double((*sx)[i])));
        max_slope_err = std::max(max_slope_err, std::fabs(double(truth.slope_z[i]) - double((*sz)[i])));
      }
    }
  }
};

// The minimum is reported next to the median: on a shared machine it is the steadier figure.
double min_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

// The fields every method reports; ours adds its own before printing.
// Every channel the sim evaluated (the choppy ones are empty unless requested).
codec::TruthView truth_of(const sim::Frame& f) {
  return {f.height, f.slope_x, f.slope_z, f.disp_x, f.disp_z, f.disp_xx, f.disp_zz, f.disp_xz};
}

common::JsonWriter common_json(const Tally& t, const Profile& p, int n, std::size_t samples) {
  const double seconds = t.frames / p.rate_hz;
  const double kbps = t.bytes * 8.0 / seconds / 1000.0;
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.text("bench", "codec").text("profile", p.name).text("method", t.method);
  if (t.lag) json.integer("lag", t.lag);
  if (t.decode_threads) json.integer("decode_threads", t.decode_threads);
  json.integer("grid", n).integer("samples", static_cast<std::int64_t>(samples));  // every cascade's
  json.integer("rate_hz", p.rate_hz).number("frames", t.frames).number("kbps", kbps);
  json.number("bits_per_sample", t.bytes * 8.0 / (t.frames * static_cast<double>(samples))).number("max_err_m", t.max_err);
  json.number("rms_err_m", std::sqrt(t.sum_sq / std::max(1.0, t.count))).number("max_slope_err", t.max_slope_err);
  json.number("height_step_m", p.height_step_m).number("slope_step", p.slope_step);
  json.number("encode_us", bench::median(t.enc_us)).number("decode_us", bench::median(t.dec_us));
  json.number("encode_us_min", min_of(t.enc_us)).number("decode_us_min", min_of(t.dec_us));
  return json;
}

// ---- baselines --------------------------------------------------------------------------------

std::int16_t q16(double v, double step) {
  const double q = std::nearbyint(v / step);
  return static_cast<std::int16_t>(std::max(-32768.0, std::min(32767.0, q)));
}

struct Zstd {
  ZSTD_CCtx* c = ZSTD_createCCtx();
  ZSTD_DCtx* d = ZSTD_createDCtx();
  ~Zstd() {
    ZSTD_freeCCtx(c);
    ZSTD_freeDCtx(d);
  }
  std::vector<std::uint8_t> compress(const std::vector<std::int16_t>& v) {
    std::vector<std::uint8_t> out(ZSTD_compressBound(v.size() * 2));
    out.resize(ZSTD_compressCCtx(c, out.data(), out.size(), v.data(), v.size() * 2, 3));
    return out;
  }
  void decompress(const std::vector<std::uint8_t>& in, std::vector<std::int16_t>& v) {
    ZSTD_decompressDCtx(d, v.data(), v.size() * 2, in.data(), in.size());
  }
};

// 16-bit planes: height at height_step, slopes at slope_step (when the profile has normals).
struct Quantized {
  static std::vector<std::int16_t> of(const sim::Frame& f, const Profile& p) {
    const std::size_t m = f.height.size();
    std::vector<std::int16_t> q(m * (p.normals ? 3 : 1));
    for (std::size_t i = 0; i < m; ++i) q[i] = q16(f.height[i], p.height_step_m);
    if (p.normals)
      for (std::size_t i = 0; i < m; ++i) {
        q[m + i] = q16(f.slope_x[i], p.slope_step);
        q[2 * m + i] = q16(f.slope_z[i], p.slope_step);
      }
    return q;
  }
  static void to_float(const std::vector<std::int16_t>& q, const Profile& p, std::size_t m, std::vector<float>& h,
                       std::vector<float>& sx, std::vector<float>& sz) {
    h.resize(m);
    for (std::size_t i = 0; i < m; ++i) h[i] = float(q[i] * double(p.height_step_m));
    if (!p.normals) return;
    sx.resize(m);
    sz.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
      sx[i] = float(q[m + i] * double(p.slope_step));
      sz[i] = float(q[2 * m + i] * double(p.slope_step));
    }
  }
};

// ---- ours ---------------------------------------------------------------------------------------

struct Ours {
  Tally tally;
  std::unique_ptr<codec::Encoder> enc;
  std::unique_ptr<codec::Decoder> dec;
  std::map<Tick, codec::StateId> ids;
  std::size_t key_bytes = 0, key_chunks = 0, chunks = 0, payload = 0, corrections = 0;
  std::size_t key_bytes_explicit = 0;  // the same key as version-1 coefficients, for comparison
  // Bytes on the wire as ocean-server sends them: one frames datagram per chunk, plus 28 bytes of
  // IPv4/UDP header each; `bundled`: each datagram also carries copies of the 2 frames before it.
  double ip_bytes = 0, ip_bytes_bundled = 0;
  std::vector<codec::Chunk> recent;  // the last two single-chunk frames, oldest first
  double height_bits = 0, slope_bits = 0;
  bool bitwise = true;
};

// Prints one JSON line per method; returns how many of ours failed the goal (within the error
// bound, at most half of delta_zstd's bitrate, decoded bit for bit as encoded).
int print_results(const Profile& p, int n, std::size_t samples, const Tally& raw, const Tally& q16z, const Tally& delta,
                  const std::vector<Ours>& ours) {
  int failures = 0;
  for (const Tally* t : {&raw, &q16z, &delta}) std::printf("%s\n", common_json(*t, p, n, samples).str().c_str());
  const double delta_kbps = delta.bytes * 8.0 / (delta.frames / p.rate_hz) / 1000.0;
  for (const Ours& o : ours) {
    const double secs = o.tally.frames / p.rate_hz;
    const double kbps = o.tally.bytes * 8.0 / secs / 1000.0;
    const bool within = o.tally.max_err <= 0.5 * double(p.height_step_m) &&
                        o.tally.max_slope_err <= 0.5 * double(p.slope_step);
    const bool pass = within && kbps <= 0.5 * delta_kbps && o.bitwise;
    failures += pass ? 0 : 1;
    common::JsonWriter line = common_json(o.tally, p, n, samples);
    line.fixed("kbps_height", o.height_bits / secs / 1000.0, 4).fixed("kbps_slope", o.slope_bits / secs / 1000.0, 4);
    line.fixed("kbps_overhead", kbps - (o.height_bits + o.slope_bits) / secs / 1000.0, 4);
    line.integer("envelope_bytes_per_chunk", codec::kEnvelopeOverheadBytes);
    line.fixed("chunks_per_frame", double(o.chunks) / o.tally.frames, 3);
    line.fixed("payload_bytes_per_frame", double(o.payload) / o.tally.frames, 2);
    line.fixed("corrections_per_frame", double(o.corrections) / o.tally.frames, 3);
    line.fixed("kbps_ip", o.ip_bytes * 8.0 / secs / 1000.0, 3);
    line.fixed("kbps_ip_redundancy2", o.ip_bytes_bundled * 8.0 / secs / 1000.0, 3);
    line.integer("key_bytes", o.key_bytes).integer("key_chunks", o.key_chunks);
    line.integer("key_bytes_explicit", o.key_bytes_explicit).boolean("bitwise_match", o.bitwise);
    line.boolean("within_bound", within).boolean("half_of_delta_zstd", kbps <= 0.5 * delta_kbps);
    std::printf("%s\n", line.str().c_str());
  }
  return failures;
}

int run_codec(int argc, char** argv) {
  std::string profiles_arg = "mobile,desktop";
  double seconds = 10.0;
  bool json = false;
  int lag = 1;
  int key_bits = 6;
  int vel_bits = 3;
  double choppiness = 1.2;
  double wind_mps = -1.0;
  CLI::App app{"ocean-bench codec: stream codec vs raw / q16+zstd / delta+zstd on real sim frames"};
  app.add_option("--profile", profiles_arg, "profile names, comma separated (mobile, desktop, desktop-choppy, mobile-choppy, lite)")->capture_default_str();
  app.add_option("--seconds", seconds, "simulated seconds per profile")->capture_default_str();
  app.add_option("--baseline-lag", lag, "ticks between a frame and its baseline (acks an RTT late); ours is also run at lag 4")
      ->capture_default_str();
  app.add_option("--key-bits", key_bits, "key precision: position rms about step * 2^-bits")->capture_default_str();
  app.add_option("--key-velocity-bits", vel_bits, "key velocity this many bits finer than position")->capture_default_str();
  app.add_option("--choppiness", choppiness, "the scene's lambda for choppy profiles (others stream no displacement)")
      ->capture_default_str()->check(CLI::Range(0.0, 100.0));
  app.add_option("--wind", wind_mps, "wind speed m/s (default: the sim's default scene)")->check(CLI::Range(0.0, 100.0));
  int decode_threads = 1;
  app.add_option("--decode-threads", decode_threads,
                 "threads each decoder spreads a frame's transforms over (the caller's and helpers, as ocean-viewer "
                 "does with cores to spare); the same bits")
      ->capture_default_str()->check(CLI::Range(1, 8));
  std::string fleet_file;
  app.add_option("--fleet", fleet_file,
                 "an ocean-server config with [[vessel]]s (client/loadtest/fleets/*.toml): frames carry their wake, "
                 "from the server's FrameProducer, and the encoder and decoder know their tracks");
  app.add_flag("--json", json, "JSON lines (the only output format)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (lag < 1 || lag > 60) {
    std::fprintf(stderr, "ocean-bench codec: --baseline-lag must be in [1, 60]\n");
    return 2;
  }
  std::optional<server::ServerConfig> fleet;
  if (!fleet_file.empty()) {
    server::ConfigLoadResult loaded = server::load_config({"ocean-bench codec", "--config", fleet_file});
    if (loaded.outcome != server::ConfigLoadResult::Outcome::run || loaded.config.vessels.empty()) {
      std::fprintf(stderr, "ocean-bench codec: --fleet %s: %s\n", fleet_file.c_str(),
                   loaded.message.empty() ? "no [[vessel]] in it" : loaded.message.c_str());
      return 2;
    }
    fleet = std::move(loaded.config);
  }
  WorkerPool pool(decode_threads - 1);
  std::vector<int> lags{lag};
  if (lag != 4) lags.push_back(4);

  std::stringstream ss(profiles_arg);
  std::string name;
  int failures = 0;
  while (std::getline(ss, name, ',')) {
    const Profile* p = find_profile(name);
    if (!p) {
      std::fprintf(stderr, "ocean-bench codec: unknown profile '%s'\n", name.c_str());
      return 2;
    }
    model::SceneParams scene;
    if (p->choppy) scene.choppiness = choppiness;
    if (wind_mps >= 0.0) scene.wind_speed_mps = wind_mps;
    sim::Ocean ocean(scene);
    // A cascaded profile's truth is its cascades' frames one after the other (its stream's fields).
    std::optional<sim::CascadeSet> cascades;
    if (!p->cascades.empty()) cascades.emplace(scene, p->cascades);
    // With a fleet, the server's own frames: the sea's, then the wake lattice of the profile's grid.
    std::unique_ptr<server::FrameProducer> producer;
    if (fleet)
      producer = std::make_unique<server::FrameProducer>(
          server::SceneSchedule(scene, {}), std::vector<const Profile*>{p},
          server::WakeSetup{fleet->wake_size_m, fleet->wake_origin_x_m, fleet->wake_origin_z_m, fleet->wake_decay_per_s,
                            fleet->vessels, p->rate_hz});
    const auto truth_at = [&](double t, sim::Frame& out) {
      if (producer)
        out = producer->produce(std::llround(t * p->rate_hz), t)->frames.front().frame;
      else if (cascades)
        cascades->evaluate(t, out, sim::FrameRequest{true, p->choppy});
      else
        ocean.evaluate_band(t, p->grid, p->grid, out, sim::FrameRequest{true, p->choppy});
    };
    const model::SceneParams model = scene;
    const int n = p->grid;
    StreamConfig config =
        StreamConfig::from_profile(*p, scene.patch_x_m, scene.patch_z_m, scene.gravity_mps2, model::wire_depth(scene.depth_m));
    if (fleet)
      config.wake = WakeLattice{p->wake_grid, fleet->wake_size_m, fleet->wake_origin_x_m, fleet->wake_origin_z_m,
                                fleet->wake_decay_per_s, 1e-6, static_cast<std::uint32_t>(sim::wake_epoch_ticks(p->rate_hz))};
    const int frames = std::max(8, static_cast<int>(seconds * p->rate_hz));
    const std::size_t m = config.samples();

    Tally raw, q16z, delta;
    raw.method = "raw_f32";
    q16z.method = "q16_zstd";
    delta.method = "delta_zstd";
    Zstd zstd;
    std::vector<std::int16_t> prev_q;  // delta_zstd: previous reconstructed frame (quantized)
    std::vector<Ours> ours(lags.size());
    for (std::size_t i = 0; i < lags.size(); ++i) {
      codec::EncoderOptions eo;
      eo.key_precision_bits = key_bits;
      eo.key_velocity_extra_bits = vel_bits;
      eo.history_ticks = 64;
      ours[i].enc = std::make_unique<codec::Encoder>(config, eo);
      codec::DecoderOptions options;
      if (pool.helpers() > 0)
        options.parallel = [&pool](int count, const std::function<void(int)>& job) { pool.run(count, job); };
      ours[i].dec = std::make_unique<codec::Decoder>(config, options);
      ours[i].enc->set_scene(0, 0, model);
      ours[i].dec->add_scene(0, 0, model);
      if (fleet) {
        ours[i].enc->set_vessels(fleet->vessels);
        ours[i].dec->set_vessels(fleet->vessels);
      }
      ours[i].tally.method = "ours";
      ours[i].tally.lag = lags[i];
      ours[i].tally.decode_threads = decode_threads;
    }

    sim::Frame f;
    std::vector<float> h, sx, sz, normals(m * 4);
    // Ticks as a server counts them about a year after its epoch: their varints cost what they
    // cost in service.
    constexpr Tick kTick0 = 1'000'000'000;
    for (int tick = 0; tick <= frames; ++tick) {
      truth_at(codec::tick_time_s(static_cast<std::int64_t>(kTick0) + tick, p->rate_hz), f);
      if (tick == 1) {  // the explicit (version 1) key of the same tick, for comparison
        codec::EncoderOptions eo;
        eo.key_precision_bits = key_bits;
        eo.key_velocity_extra_bits = vel_bits;
        eo.modeled_key_max_correction_share = -1.0;
        codec::Encoder explicit_keys(config, eo);
        explicit_keys.set_scene(0, 0, model);
        if (fleet) explicit_keys.set_vessels(fleet->vessels);
        sim::Frame before;
        truth_at(codec::tick_time_s(static_cast<std::int64_t>(kTick0), p->rate_hz), before);
        explicit_keys.add_truth(kTick0, truth_of(before));
        explicit_keys.add_truth(kTick0 + 1, truth_of(f));
        for (const Chunk& c : explicit_keys.encode_key(kTick0 + 1)->chunks)
          for (Ours& o : ours) o.key_bytes_explicit += c.payload.size();
      }
      const bool steady = tick >= 2;  // tick 1 is the key for ours; the baselines skip it too

      // raw_f32: height + unit normal (-sx, 1, -sz)/len per vertex.
      double t0 = bench::now_ms();
      for (std::size_t i = 0; i < m; ++i) {
        const float nx = -f.slope_x[i], nz = -f.slope_z[i];
        const float inv = 1.0f / std::sqrt(nx * nx + 1.0f + nz * nz);
        normals[4 * i] = f.height[i];
        normals[4 * i + 1] = nx * inv;
        normals[4 * i + 2] = inv;
        normals[4 * i + 3] = nz * inv;
      }
      std::vector<float> wire(normals);
      double t1 = bench::now_ms();
      h.assign(m, 0.0f);
      for (std::size_t i = 0; i < m; ++i) h[i] = wire[4 * i];
      double t2 = bench::now_ms();
      if (steady) {
        raw.bytes += double(m) * 16;
        raw.frames += 1;
        raw.enc_us.push_back((t1 - t0) * 1000);
        raw.dec_us.push_back((t2 - t1) * 1000);
        raw.error(f, h, nullptr, nullptr);
      }

      // q16_zstd
      t0 = bench::now_ms();
      const auto q = Quantized::of(f, *p);
      const auto packed = zstd.compress(q);
      t1 = bench::now_ms();
      std::vector<std::int16_t> back(q.size());
      zstd.decompress(packed, back);
      Quantized::to_float(back, *p, m, h, sx, sz);
      t2 = bench::now_ms();
      if (steady) {
        q16z.bytes += double(packed.size());
        q16z.frames += 1;
        q16z.enc_us.push_back((t1 - t0) * 1000);
        q16z.dec_us.push_back((t2 - t1) * 1000);
        q16z.error(f, h, p->normals ? &sx : nullptr, p->normals ? &sz : nullptr);
      }

      // delta_zstd: difference from the previous reconstructed (quantized) frame.
      t0 = bench::now_ms();
      std::vector<std::int16_t> d(q.size());
      for (std::size_t i = 0; i < q.size(); ++i) d[i] = static_cast<std::int16_t>(q[i] - (prev_q.empty() ? 0 : prev_q[i]));
      const auto dpacked = zstd.compress(d);
      t1 = bench::now_ms();
      std::vector<std::int16_t> dback(d.size());
      zstd.decompress(dpacked, dback);
      for (std::size_t i = 0; i < dback.size(); ++i)
        dback[i] = static_cast<std::int16_t>(dback[i] + (prev_q.empty() ? 0 : prev_q[i]));
      Quantized::to_float(dback, *p, m, h, sx, sz);
      t2 = bench::now_ms();
      prev_q = dback;
      if (steady) {
        delta.bytes += double(dpacked.size());
        delta.frames += 1;
        delta.enc_us.push_back((t1 - t0) * 1000);
        delta.dec_us.push_back((t2 - t1) * 1000);
        delta.error(f, h, p->normals ? &sx : nullptr, p->normals ? &sz : nullptr);
      }

      // ours: key at tick 1 (its velocity needs tick 0), then deltas from tick - lag (tick 1 at first).
      for (Ours& o : ours) {
        const Tick t = kTick0 + static_cast<Tick>(tick);
        t0 = bench::now_ms();
        o.enc->add_truth(t, truth_of(f));
        if (tick == 0) continue;
        std::shared_ptr<const codec::EncodedFrame> e;
        if (tick == 1)
          e = o.enc->encode_key(t);
        else
          e = o.enc->encode_delta(t, o.ids.at(std::max<Tick>(kTick0 + 1, t - static_cast<Tick>(o.tally.lag))));
        t1 = bench::now_ms();
        o.ids[t] = e->id;
        for (const Chunk& c : e->chunks)
          if (o.dec->accept(c) != codec::ChunkError::ok) o.bitwise = false;
        const codec::ReconstructedFrame* r = o.dec->latest();
        t2 = bench::now_ms();
        if (!r || r->tick != t || !r->complete || r->height != e->reconstruction.height ||
            r->slope_x != e->reconstruction.slope_x || r->slope_z != e->reconstruction.slope_z ||
            r->disp_x != e->reconstruction.disp_x || r->jacobian != e->reconstruction.jacobian)
          o.bitwise = false;
        std::size_t bytes = 0;
        for (const Chunk& c : e->chunks) bytes += c.payload.size();
        if (e->key) {
          o.key_bytes += bytes;
          o.key_chunks += e->chunks.size();
          continue;
        }
        o.tally.bytes += double(bytes + e->chunks.size() * codec::kEnvelopeOverheadBytes);
        for (const Chunk& c : e->chunks) {
          const protocol::FrameRecord record = server::record_of(c);
          o.ip_bytes += double(protocol::frames_datagram(std::span(&record, 1)).size() + codec::kIpUdpHeaderBytes);
        }
        if (e->chunks.size() == 1) {
          std::vector<protocol::FrameRecord> bundle;
          for (const Chunk& c : o.recent) bundle.push_back(server::record_of(c));
          const Chunk& c = e->chunks.front();
          bundle.push_back(server::record_of(c));
          o.ip_bytes_bundled += double(protocol::frames_datagram(bundle).size() + codec::kIpUdpHeaderBytes);
          o.recent.push_back(c);
          if (o.recent.size() > 2) o.recent.erase(o.recent.begin());
        }
        o.tally.frames += 1;
        o.payload += bytes;
        o.chunks += e->chunks.size();
        o.corrections += e->stats.corrections_height + e->stats.corrections_slope;
        o.height_bits += e->stats.cost.height_bits;
        o.slope_bits += e->stats.cost.slope_bits;
        o.tally.enc_us.push_back((t1 - t0) * 1000);
        o.tally.dec_us.push_back((t2 - t1) * 1000);
        o.tally.error(f, r->height, p->normals ? &r->slope_x : nullptr, p->normals ? &r->slope_z : nullptr);
      }
    }

    failures += print_results(*p, n, m, raw, q16z, delta, ours);
    std::fflush(stdout);
  }
  (void)json;
  return failures ? 1 : 0;
}

const ocean::bench::Registrar codec_bench("codec", "stream codec bitrate/error/cost vs raw, q16+zstd, delta+zstd", run_codec);

}  // namespace
