// Encoder: prediction, correction decisions, chunking (CODEC.md 7, 8).
#include "encoder.hpp"

#include "det_math.hpp"
#include "fixed_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ocean::codec {
namespace {

// round(x / 2^s), ties away from zero (s may be 0).
std::int64_t shift_round(std::int64_t x, int s) { return s == 0 ? x : mul_round_sym(x, 1, s); }

// Corrections for one channel: wherever the float output would miss the truth by more than half
// a step, add the nearest multiple of a quarter step (the result is then within step / 8).
void correct_channel(std::vector<std::int64_t>& pred, std::span<const float> truth, double unit, double step,
                     int quantum_shift, std::vector<Correction>& out) {
  const double quantum = step / 4.0;
  for (std::size_t i = 0; i < pred.size(); ++i) {
    const double t = static_cast<double>(truth[i]);
    const double shown = static_cast<double>(static_cast<float>(static_cast<double>(pred[i]) * unit));
    if (std::fabs(t - shown) <= 0.5 * step) continue;
    double q = std::nearbyint((t - static_cast<double>(pred[i]) * unit) / quantum);
    q = std::clamp(q, -static_cast<double>(kMaxCorrection), static_cast<double>(kMaxCorrection));
    const auto c = static_cast<std::int32_t>(q);
    if (c == 0) continue;
    out.push_back({static_cast<std::uint32_t>(i), c});
    pred[i] = wadd(pred[i], wshl(c, quantum_shift));
  }
}

}  // namespace

Encoder::Encoder(const StreamConfig& config, EncoderOptions options)
    : config_(config), options_(options), model_(config), scenes_(config) {
  if (options.max_payload < 64 || options.max_payload > 65000)
    throw std::invalid_argument("EncoderOptions.max_payload = " + std::to_string(options.max_payload) +
                                ": must be in [64, 65000]");
  if (options.history_ticks < 1 || options.history_ticks > 100000)
    throw std::invalid_argument("EncoderOptions.history_ticks must be in [1, 100000]");
  if (options.key_precision_bits < 0 || options.key_precision_bits > 16)
    throw std::invalid_argument("EncoderOptions.key_precision_bits = " + std::to_string(options.key_precision_bits) +
                                ": must be in [0, 16]");
  if (options.key_velocity_extra_bits < 0 || options.key_velocity_extra_bits > 16)
    throw std::invalid_argument("EncoderOptions.key_velocity_extra_bits must be in [0, 16]");
}

void Encoder::set_scene(Tick from, std::uint8_t tag, const model::SceneParams& scene) {
  scenes_.add(from, tag, scene);
  advanced_.clear();  // advanced under the timeline as it was
  predictions_.clear();
}

namespace {

// Copies a field, clamping values beyond the stream's 2^20 steps to the last step and non-finite
// ones to 0; returns how many it changed. A scene the server let through should never need it
// (server/net/config/servable_scene.hpp): if one does, its stream degrades there and says so, instead of
// stopping the server.
std::uint64_t clamped_copy(std::span<const float> in, float step, std::vector<float>& out) {
  const float limit = static_cast<float>(std::ldexp(static_cast<double>(step), 20) - static_cast<double>(step));
  std::uint64_t clamped = 0;
  out.resize(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const float v = in[i];
    if (std::fabs(v) <= limit) {
      out[i] = v;
      continue;
    }
    ++clamped;
    out[i] = std::isnan(v) ? 0.0f : std::copysign(limit, v);
  }
  return clamped;
}

}  // namespace

void Encoder::add_truth(Tick tick, const TruthView& truth) {
  const std::size_t nn = model_.samples();
  for (int ch = 0; ch < kChannelCount; ++ch)
    if (carries(config_, kChannels[ch]) && truth[ch].size() != nn)
      throw std::invalid_argument("Encoder::add_truth: " + std::string(kChannels[ch].name) + " has " +
                                  std::to_string(truth[ch].size()) + " samples, the stream's lattices need " +
                                  std::to_string(nn) + " (" + std::string(carrier(kChannels[ch].group)) +
                                  " carries it)");
  TruthFrame& f = truth_[tick];
  for (int ch = 0; ch < kChannelCount; ++ch)
    if (carries(config_, kChannels[ch])) saturated_ += clamped_copy(truth[ch], static_cast<float>(step_of(config_, kChannels[ch].unit)), f[ch]);
  if (tick == predictions_tick_) predictions_.clear();  // corrected against the truth it replaces
  if (!have_truth_ || tick > newest_) newest_ = tick;
  have_truth_ = true;
  evict();
}

void Encoder::evict() {
  if (newest_ < options_.history_ticks) return;
  const Tick oldest = newest_ - options_.history_ticks;
  const Tick key_span = std::max(options_.history_ticks, options_.key_history_ticks);
  const Tick oldest_key = newest_ > key_span ? newest_ - key_span : 0;
  while (!truth_.empty() && truth_.begin()->first < oldest) truth_.erase(truth_.begin());
  std::erase_if(states_, [&](const auto& item) {
    const StateId id = item.first;
    if (id.tick >= oldest) return false;
    if (id.tick < oldest_key) return true;
    const auto key = key_ids_.find(id.tick);
    return key == key_ids_.end() || key->second != id;
  });
  std::erase_if(advanced_, [&](const auto& item) { return states_.count(item.first) == 0; });
  while (!key_ids_.empty() && key_ids_.begin()->first < oldest_key) key_ids_.erase(key_ids_.begin());
  const Tick oldest_frame =
      options_.frame_cache_ticks == 0 ? oldest : (newest_ >= options_.frame_cache_ticks ? newest_ - options_.frame_cache_ticks + 1 : 0);
  const Tick oldest_key_frame = options_.frame_cache_ticks == 0 ? oldest_key : oldest_frame;
  while (!keys_.empty() && keys_.begin()->first < oldest_key_frame) keys_.erase(keys_.begin());
  while (!deltas_.empty() && deltas_.begin()->first.first < oldest_frame) deltas_.erase(deltas_.begin());
  scenes_.forget_before(states_.empty() ? oldest : std::min(oldest, states_.begin()->first.tick));
}

bool Encoder::forget_states() {
  if (states_.empty() && keys_.empty() && deltas_.empty()) return false;
  states_.clear();
  advanced_.clear();
  keys_.clear();
  key_ids_.clear();
  deltas_.clear();
  predictions_.clear();
  return true;
}

const ModalState* Encoder::state(StateId id) const {
  auto it = states_.find(id);
  return it == states_.end() ? nullptr : &it->second;
}

std::shared_ptr<const EncodedFrame> Encoder::encode_key(Tick tick) {
  if (auto it = keys_.find(tick); it != keys_.end()) return it->second;
  if (truth_.find(tick) == truth_.end())
    throw std::invalid_argument("Encoder::encode_key(" + std::to_string(tick) + "): no truth for this tick");
  if (!scenes_.at(tick))
    throw std::invalid_argument("Encoder::encode_key(" + std::to_string(tick) + "): no scene set for this tick");
  ModalState predicted;
  scenes_.model_state(tick, predicted);
  const Corrections corrections = correct_once(tick, predicted);
  const double samples =
      static_cast<double>(model_.samples()) * (1 + (config_.normals ? 2 : 0) + (config_.choppy ? 5 : 0));
  if (static_cast<double>(corrections.total()) > options_.modeled_key_max_correction_share * samples &&
      tick > 0 && truth_.count(tick - 1) != 0)
    return explicit_key(tick);
  const KeyCoding coding;
  auto frame = finish_frame(tick, std::move(predicted), corrections, &coding, {});
  keys_[tick] = frame;
  key_ids_[tick] = frame->id;
  return frame;
}

// The codec version 1 key: spectra of the truth at tick and tick - 1, quantized (CODEC.md 7.3).
std::shared_ptr<const EncodedFrame> Encoder::explicit_key(Tick tick) {
  const auto &t1 = truth_.at(tick), &t0 = truth_.at(tick - 1);
  const std::size_t nn = model_.samples();
  const double step = static_cast<double>(config_.height_step_m);
  std::vector<std::int64_t> f1(nn), f0(nn);
  for (std::size_t i = 0; i < nn; ++i) {
    f1[i] = model::to_fixed(static_cast<double>(t1[ChannelId::height][i]) / step, kHeightFracBits);
    f0[i] = model::to_fixed(static_cast<double>(t0[ChannelId::height][i]) / step, kHeightFracBits);
  }
  HalfSpectrum s1, s0;
  model_.spectrum_of(f1.data(), s1);
  model_.spectrum_of(f0.data(), s0);
  // Spectral quantization error 2^p per coefficient gives spatial rms about 2^p / (n sqrt 6):
  // choose p for an rms of step * 2^-key_precision_bits on the smallest lattice.
  int log2n = 30;
  for (const StreamConfig::Lattice& l : model_.lattices()) log2n = std::min(log2n, log2_of(l.n));
  KeyCoding coding;
  coding.modeled = false;
  coding.pos_shift = std::max(0, kHeightFracBits - options_.key_precision_bits + log2n + 1);
  coding.vel_shift = std::max(0, coding.pos_shift - options_.key_velocity_extra_bits);
  const auto& modes = model_.key_modes();
  coding.coefficients.resize(modes.size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const std::int32_t at = modes[i];
    KeyCoefficient& k = coding.coefficients[i];
    k.xr = shift_round(s1.re[at], coding.pos_shift);
    k.xi = shift_round(s1.im[at], coding.pos_shift);
    k.vr = shift_round(s1.re[at] - s0.re[at], coding.vel_shift);
    k.vi = shift_round(s1.im[at] - s0.im[at], coding.vel_shift);
  }
  ModalState predicted = key_state(model_, coding.coefficients, coding.pos_shift, coding.vel_shift);
  const Corrections corrections = correct(tick, predicted);
  auto frame = finish_frame(tick, std::move(predicted), corrections, &coding, {});
  keys_[tick] = frame;
  key_ids_[tick] = frame->id;
  return frame;
}

std::shared_ptr<const EncodedFrame> Encoder::encode_delta(Tick tick, StateId baseline) {
  const auto cache_key = std::make_pair(tick, baseline);
  if (auto it = deltas_.find(cache_key); it != deltas_.end()) return it->second;
  if (baseline.tick >= tick)
    throw std::invalid_argument("Encoder::encode_delta: baseline tick " + std::to_string(baseline.tick) +
                                " must be older than tick " + std::to_string(tick));
  auto st = states_.find(baseline);
  if (st == states_.end())
    throw std::invalid_argument("Encoder::encode_delta: baseline state {" + std::to_string(baseline.tick) + ", " +
                                std::to_string(baseline.serial) + "} is not held (evicted or never encoded)");
  if (truth_.find(tick) == truth_.end())
    throw std::invalid_argument("Encoder::encode_delta: no truth for tick " + std::to_string(tick));
  if (!scenes_.at(baseline.tick))
    throw std::invalid_argument("Encoder::encode_delta: no scene set for tick " + std::to_string(baseline.tick));
  ModalState predicted = advanced_[baseline].advance(st->second, baseline.tick, tick, scenes_);
  const Corrections corrections = correct_once(tick, predicted);
  auto frame = finish_frame(tick, std::move(predicted), corrections, nullptr, baseline);
  deltas_[cache_key] = frame;
  return frame;
}

Corrections Encoder::correct_once(Tick tick, const ModalState& predicted) {
  if (predictions_tick_ != tick) {
    predictions_.clear();
    predictions_tick_ = tick;
  }
  for (const Prediction& p : predictions_)
    if (p.state == predicted) {
      fields_ = p.fields;
      return p.corrections;
    }
  Corrections corrections = correct(tick, predicted);
  if (predictions_.size() < kMaxPredictionsPerTick) predictions_.push_back({predicted, corrections, fields_});
  return corrections;
}

// Synthesizes the prediction into fields_ and returns the corrections that bring every sample
// within half a step of the truth (fields_ then holds exactly what the decoder shows).
Corrections Encoder::correct(Tick tick, const ModalState& predicted) {
  const TruthFrame& truth = truth_.at(tick);
  model_.synthesize(predicted.cur, scenes_.at(tick)->scene.choppiness, fields_);
  Corrections corr;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const ChannelUnit unit = kChannels[ch].unit;
    if (!carries(config_, kChannels[ch])) continue;
    correct_channel(fields_[ch], truth[ch], unit_scale(config_, unit), step_of(config_, unit), quantum_shift(unit),
                    corr[ch]);
  }
  return corr;
}

// key == nullptr: a delta from `base`. fields_ holds the corrected prediction (correct()).
std::shared_ptr<EncodedFrame> Encoder::finish_frame(Tick tick, ModalState predicted, const Corrections& corr,
                                                    const KeyCoding* key, StateId base) {
  auto frame = std::make_shared<EncodedFrame>();
  frame->key = key != nullptr;
  frame->id = {tick, next_serial_++};
  frame->base = key ? frame->id : base;
  std::size_t* by_group[] = {&frame->stats.corrections_height, &frame->stats.corrections_slope,
                             &frame->stats.corrections_choppy};
  for (int ch = 0; ch < kChannelCount; ++ch) *by_group[static_cast<int>(kChannels[ch].group)] += corr[ch].size();
  frame->reconstruction.tick = tick;
  frame->reconstruction.complete = true;
  to_float(fields_, config_, frame->reconstruction);

  const bool explicit_key = key && !key->modeled;
  BodyLayout layout;
  layout.spectral_items = explicit_key ? static_cast<std::uint32_t>(model_.key_modes().size()) : 0;
  layout.samples = static_cast<std::uint32_t>(model_.samples());
  layout.normals = config_.normals;
  layout.choppy = config_.choppy;
  ChunkHeader proto;
  proto.key = key != nullptr;
  proto.modeled = key && key->modeled;
  proto.normals = config_.normals;
  proto.choppy = config_.choppy;
  proto.cascaded = !config_.cascades.empty();
  proto.wake = config_.has_wake();
  proto.scene_tag = scenes_.at(tick)->tag;
  proto.pos_shift = static_cast<std::uint8_t>(explicit_key ? key->pos_shift : 0);
  proto.vel_shift = static_cast<std::uint8_t>(explicit_key ? key->vel_shift : 0);
  static const std::vector<KeyCoefficient> kNoCoefficients;
  chunk_frame(*frame, layout, proto, explicit_key ? key->coefficients : kNoCoefficients, corr);

  if (!corr[ChannelId::height].empty())
    model_.add_correction(predicted, height_correction_field(model_.samples(), corr[ChannelId::height]), key ? 0 : tick - base.tick);
  // Deltas of one tick from different baselines often land on the same state (without
  // corrections, advancing is path-independent): one id for one state lets later deltas from
  // either be encoded once for every client.
  if (!key)
    for (auto it = states_.lower_bound(StateId{tick, 0}); it != states_.end() && it->first.tick == tick; ++it)
      if (it->second == predicted) {
        frame->id = it->first;
        return frame;
      }
  states_[frame->id] = std::move(predicted);
  return frame;
}

}  // namespace ocean::codec
