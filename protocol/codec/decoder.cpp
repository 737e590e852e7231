// Decoder: validation order, frame assembly, completion (CODEC.md 9).
#include "decoder.hpp"

#include <stdexcept>
#include <string>

namespace ocean::codec {

Decoder::Decoder(const StreamConfig& config, DecoderOptions options)
    : config_(config), options_(options), model_(config), scenes_(config) {
  if (options.history_ticks < 1 || options.max_lag < 1 || options.max_pending < 1)
    throw std::invalid_argument("DecoderOptions: history_ticks, max_lag and max_pending must be >= 1");
  if (options.memo && !(options.memo->config() == config))
    throw std::invalid_argument("DecoderOptions: the memo belongs to another stream configuration");
  if (options.memo) scenes_.share_models(&options.memo->models());
  // Below 128 x 128 a frame's pieces take less than waking a thread: one thread does them.
  if (config.grid >= 128) parallel_ = options_.parallel;
  if (parallel_) model_.set_parallel(parallel_);
}

std::optional<Tick> Decoder::newest_complete() const {
  if (states_.empty()) return std::nullopt;
  return states_.rbegin()->first;
}

std::vector<Tick> Decoder::complete_ticks() const {
  std::vector<Tick> v;
  for (const auto& [t, s] : states_) v.push_back(t);
  return v;
}

const ModalState* Decoder::state(Tick tick) const {
  auto it = states_.find(tick);
  return it == states_.end() ? nullptr : it->second.get();
}

ChunkError Decoder::check(const ChunkView& c, const ChunkHeader& h, const BodyLayout& layout) const {
  if (h.normals != config_.normals || h.choppy != config_.choppy || h.cascaded != !config_.cascades.empty() ||
      h.wake != config_.has_wake())
    return ChunkError::wrong_dimensions;
  if (h.item_begin >= h.item_end || h.item_end > layout.total()) return ChunkError::bad_range;
  if (h.key && !h.modeled && (h.pos_shift > 40 || h.vel_shift > 40)) return ChunkError::bad_value;
  if (c.count == 0 || c.count > kMaxChunksPerFrame || c.index >= c.count) return ChunkError::bad_index;
  if (c.key ? c.baseline != c.tick : c.baseline >= c.tick) return ChunkError::bad_baseline;
  if (!c.key && c.tick - c.baseline > options_.max_lag) return ChunkError::lag_too_large;
  if (const SceneTimeline::Entry* scene = scenes_.at(c.tick); !scene || scene->tag != h.scene_tag)
    return ChunkError::unknown_scene;
  if (const auto newest = newest_complete(); newest && c.tick <= *newest && *newest - c.tick >= options_.history_ticks)
    return ChunkError::stale_tick;
  if (states_.count(c.tick)) return ChunkError::duplicate_chunk;
  if (!c.key && !states_.count(c.baseline)) return ChunkError::unknown_baseline;
  if (auto it = pending_.find(c.tick); it != pending_.end()) {
    const Pending& p = it->second;
    if (p.key != c.key || p.modeled != h.modeled || p.baseline != c.baseline || p.count != c.count)
      return ChunkError::inconsistent_frame;
    if (p.got[c.index]) return ChunkError::duplicate_chunk;
    std::uint64_t covered = h.item_end - h.item_begin;
    for (const auto& [b, e] : p.ranges) {
      if (h.item_begin < e && b < h.item_end) return ChunkError::overlapping_range;
      covered += e - b;
    }
    if (p.received + 1 == p.count && covered != layout.total()) return ChunkError::coverage_mismatch;
  } else if (c.count == 1 && !h.whole) {
    return ChunkError::coverage_mismatch;
  }
  return ChunkError::ok;
}

// A chunk of a tick not seen before: the frame's bookkeeping, and the prediction its corrections
// apply to (none for an explicit key, whose coefficients are the frame).
void Decoder::start_pending(Pending& p, const ChunkView& c, const ChunkHeader& h, std::uint32_t spectral_items) {
  p.baseline = c.baseline;
  p.key = c.key;
  p.modeled = h.modeled;
  p.count = c.count;
  p.fields = std::move(spare_fields_);
  p.got.assign(c.count, false);
  if (c.key && options_.memo) p.key_payloads.resize(c.count);
  if (c.key && !h.modeled) {
    p.key_coefficients.resize(spectral_items);
    p.pos_shift = h.pos_shift;
    p.vel_shift = h.vel_shift;
  } else {
    if (c.key) {
      scenes_.model_state(c.tick, p.predicted);
    } else {
      if (options_.memo) {
        options_.memo->advance(states_.at(c.baseline), c.baseline, c.tick, scenes_, p.predicted);
      } else {
        p.predicted = std::move(spare_state_);  // its buffers, if any: advancing then allocates nothing
        scenes_.advance(*states_.at(c.baseline), c.baseline, c.tick, p.predicted, parallel_);
      }
    }
    model_.synthesize(p.predicted.cur, scenes_.at(c.tick)->scene.choppiness, p.fields.synthesis);
  }
}

ChunkError Decoder::accept(const ChunkView& c) {
  completed_tick_.reset();
  ChunkHeader h;
  std::span<const std::uint8_t> body;
  if (const ChunkError e = parse_payload(c, options_.max_payload, config_.grid_log2(), h, body); e != ChunkError::ok)
    return e;
  BodyLayout layout;
  layout.spectral_items = h.key && !h.modeled ? static_cast<std::uint32_t>(model_.key_modes().size()) : 0;
  layout.samples = static_cast<std::uint32_t>(model_.samples());
  layout.normals = config_.normals;
  layout.choppy = config_.choppy;
  if (h.whole) {
    h.item_begin = 0;
    h.item_end = layout.total();
  }
  if (const ChunkError e = check(c, h, layout); e != ChunkError::ok) return e;
  if (accept_remembered(c)) return ChunkError::ok;
  // A scene whose model cannot be built for this stream names no state the decoder could use.
  if (!pending_.count(c.tick) && (h.modeled || !c.key) && !scenes_.prepare(c.baseline, c.tick, c.key))
    return ChunkError::unknown_scene;
  DecodedBody decoded;
  if (!decode_body(layout, h.item_begin, h.item_end, body, decoded)) return ChunkError::bad_value;

  // Everything below changes state and cannot fail.
  auto [it, fresh] = pending_.try_emplace(c.tick);
  Pending& p = it->second;
  if (fresh) start_pending(p, c, h, layout.spectral_items);
  p.got[c.index] = true;
  if (!p.key_payloads.empty()) p.key_payloads[c.index].assign(c.payload.begin(), c.payload.end());
  ++p.received;
  p.ranges.emplace_back(h.item_begin, h.item_end);
  for (std::size_t i = 0; i < decoded.key.size(); ++i) p.key_coefficients[h.item_begin + i] = decoded.key[i];
  const bool predicted = !c.key || h.modeled;  // fields hold a prediction to correct and show
  auto append = [](std::vector<Correction>& to, const std::vector<Correction>& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  for (int ch = 0; ch < kCorrectionChannels; ++ch) append(p.fields.corrections[ch], decoded.corrections[ch]);

  if (predicted && (!shown_tick_ || c.tick >= *shown_tick_)) show(c.tick);
  if (p.received == p.count) {
    complete(c.tick, p, c.payload);
    recycle(std::move(p.fields));  // still here when the memo took a copy of the frame
    pending_.erase(c.tick);
  }
  while (pending_.size() > options_.max_pending) drop_pending(pending_.begin());
  evict();
  return ChunkError::ok;
}

Tick Decoder::baseline_of(Tick tick, const Pending& p) { return p.key ? tick : p.baseline; }

void Decoder::show(Tick tick) {
  shown_tick_ = tick;
  shown_dirty_ = true;
  shown_shared_.reset();
}

// A single-chunk frame whose exact bytes the memo has seen: a key of this tick, or a delta on this
// very baseline state. Before any work: a modeled key would otherwise build its model state first.
bool Decoder::accept_remembered(const ChunkView& c) {
  DecodeMemo* memo = options_.memo;
  if (!memo || c.count != 1) return false;
  const DecodeMemo::Result* r =
      c.key ? memo->find_key(c.tick, c.payload) : memo->find(states_.at(c.baseline), c.tick, c.payload);
  if (!r) return false;
  complete_shared(c.tick, *r);
  evict();
  return true;
}

void Decoder::complete(Tick tick, Pending& p, std::span<const std::uint8_t> payload) {
  DecodeMemo* memo = options_.memo;
  // The memo takes keys and single-chunk deltas, by their bytes.
  if (memo && p.key) {
    if (const DecodeMemo::Result* r = memo->find_key(tick, p.key_payloads)) {
      complete_shared(tick, *r);
      return;
    }
  }
  if (p.key && !p.modeled) {
    p.predicted = key_state(model_, p.key_coefficients, p.pos_shift, p.vel_shift);
    model_.synthesize(p.predicted.cur, scenes_.at(tick)->scene.choppiness, p.fields.synthesis);
  }
  if (!p.fields.corrections[ChannelId::height].empty())
    model_.add_correction(p.predicted, height_correction_field(model_.samples(), p.fields.corrections[ChannelId::height]),
                         p.key ? 0 : tick - p.baseline);
  const DecodeMemo::State state = memo ? memo->intern(tick, std::move(p.predicted))
                                       : DecodeMemo::State(std::make_shared<ModalState>(std::move(p.predicted)));
  const bool shown = !shown_tick_ || tick >= *shown_tick_;
  completed_tick_ = tick;
  late_shared_.reset();
  late_converted_ = false;
  if (memo && (p.key || p.count == 1)) {
    ReconstructedFrame frame;
    to_float(p.fields.synthesis, p.fields.corrections, config_, frame, parallel_);
    frame.tick = tick;
    frame.baseline = baseline_of(tick, p);
    frame.complete = true;
    const DecodeMemo::Result& r =
        p.key ? memo->remember_key(tick, p.key_payloads, state, std::move(frame))
              : memo->remember(states_.at(p.baseline), tick, payload, state, std::move(frame));
    complete_shared(tick, r);
    return;
  }
  if (shown) {
    show(tick);
    recycle(std::move(shown_fields_));
    shown_fields_ = std::move(p.fields);
    shown_complete_ = true;
    shown_baseline_ = baseline_of(tick, p);
  } else {
    recycle(std::move(late_fields_));
    late_fields_ = std::move(p.fields);
    late_baseline_ = baseline_of(tick, p);
  }
  hold(tick, state);
}

// A complete frame whose state and shown frame the memo holds.
void Decoder::complete_shared(Tick tick, const DecodeMemo::Result& r) {
  completed_tick_ = tick;
  late_converted_ = false;
  hold(tick, r.state);
  if (!shown_tick_ || tick >= *shown_tick_) {
    show(tick);
    shown_shared_ = r.frame;
    shown_complete_ = true;
    shown_dirty_ = false;
    late_shared_.reset();
  } else {
    late_shared_ = r.frame;
  }
}

const ReconstructedFrame* Decoder::just_completed() {
  if (!completed_tick_) return nullptr;
  if (shown_tick_ && *completed_tick_ == *shown_tick_) return latest();
  if (late_shared_) return late_shared_.get();
  if (!late_converted_) {
    to_float(late_fields_.synthesis, late_fields_.corrections, config_, late_, parallel_);
    late_.tick = *completed_tick_;
    late_.baseline = late_baseline_;
    late_.complete = true;
    late_.shared_id = 0;
    late_converted_ = true;
  }
  return &late_;
}

void Decoder::hold(Tick tick, DecodeMemo::State state) {
  states_[tick] = std::move(state);
  window_ = window_ ? window_->with(tick) : protocol::AckWindow{tick, 0};
}

void Decoder::evict() {
  const auto newest = newest_complete();
  if (!newest || *newest < options_.history_ticks) return;
  const Tick oldest = *newest - options_.history_ticks;
  while (!states_.empty() && states_.begin()->first < oldest) {
    window_ = window_->without(states_.begin()->first);
    recycle(std::move(states_.begin()->second));
    states_.erase(states_.begin());
  }
  while (!pending_.empty() && pending_.begin()->first < oldest) drop_pending(pending_.begin());
  scenes_.forget_before(states_.empty() ? oldest : std::min(oldest, states_.begin()->first));
}

// Without a memo every held state was made by complete() as a (non-const) ModalState; the last
// reference to one may give its buffers to the next delta's copy of its baseline.
void Decoder::recycle(DecodeMemo::State&& state) {
  if (options_.memo || !state || state.use_count() != 1) return;
  spare_state_ = std::move(const_cast<ModalState&>(*state));
}

void Decoder::drop_pending(std::map<Tick, Pending>::iterator it) {
  // The frame on show keeps showing what it had, still marked incomplete.
  if (shown_tick_ && it->first == *shown_tick_) {
    show(it->first);
    recycle(std::move(shown_fields_));
    shown_fields_ = std::move(it->second.fields);
    shown_complete_ = false;
    shown_baseline_ = baseline_of(it->first, it->second);
  } else {
    recycle(std::move(it->second.fields));
  }
  pending_.erase(it);
}

const ReconstructedFrame* Decoder::latest() {
  if (!shown_tick_) return nullptr;
  if (shown_shared_) return shown_shared_.get();
  if (shown_dirty_) {
    auto it = pending_.find(*shown_tick_);
    const bool held = it == pending_.end();
    const FrameFields& fields = held ? shown_fields_ : it->second.fields;
    to_float(fields.synthesis, fields.corrections, config_, shown_, parallel_);
    shown_.tick = *shown_tick_;
    shown_.baseline = held ? shown_baseline_ : baseline_of(*shown_tick_, it->second);
    shown_.complete = held && shown_complete_;
    shown_dirty_ = false;
  }
  return &shown_;
}

}  // namespace ocean::codec
