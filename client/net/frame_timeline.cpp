// FrameTimeline: buffering, render clock and frame choice.
#include "frame_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ocean::client {

FrameTimeline::FrameTimeline(FrameTimelineConfig config)
    : config_(config), clock_(config.tick_period_s, config.clock_window) {
  if (config.capacity < 2) throw std::invalid_argument("FrameTimelineConfig.capacity must be >= 2 frames");
  if (!(config.max_clock_slew > 0.0 && config.max_clock_slew < 1.0))
    throw std::invalid_argument("FrameTimelineConfig.max_clock_slew must be in (0, 1)");
  const double interval = config.send_interval_s > 0.0 ? config.send_interval_s : config.tick_period_s;
  delay_s_ = config.interpolation_delay_s > 0.0 ? config.interpolation_delay_s : config.delay_intervals * interval;
  send_interval_s_ = interval;
  frames_.resize(config.capacity);
  used_.assign(config.capacity, false);
}

std::size_t FrameTimeline::frames_held() const {
  return static_cast<std::size_t>(std::count(used_.begin(), used_.end(), true));
}

void FrameTimeline::clear() {
  used_.assign(used_.size(), false);
  clock_.reset();
  rendering_ = false;
  starved_ = false;
}

TimelineFrame* FrameTimeline::slot_for(Tick tick) {
  std::size_t oldest = frames_.size();
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (!used_[i]) return &frames_[i];
    if (frames_[i].tick == tick) return frames_[i].predicted ? &frames_[i] : nullptr;  // duplicate
    if (oldest == frames_.size() || frames_[i].tick < frames_[oldest].tick) oldest = i;
  }
  if (frames_[oldest].tick > tick) return nullptr;  // older than everything held, and no room
  return &frames_[oldest];
}

void FrameTimeline::push(const codec::ReconstructedFrame& frame, Tick tick, double arrival_s) {
  // A tick far behind what is held means the server restarted its clock: start over.
  for (std::size_t i = 0; i < frames_.size(); ++i)
    if (used_[i] && frames_[i].tick > tick &&
        (frames_[i].tick - tick) * config_.tick_period_s > config_.clock_snap_s) {
      clear();
      break;
    }
  TimelineFrame* slot = slot_for(tick);
  if (!slot) {
    ++counters_.frames_discarded;
    return;
  }
  ++counters_.frames_pushed;
  if (rendering_ && static_cast<double>(tick) < last_render_tick_) ++counters_.frames_late;
  clock_.observe(tick, arrival_s);
  fill(*slot, frame, tick, arrival_s, false);
}

void FrameTimeline::fill(TimelineFrame& slot, const codec::ReconstructedFrame& frame, Tick tick,
                         double arrival_s, bool predicted) {
  slot.tick = tick;
  slot.arrival_s = arrival_s;
  slot.predicted = predicted;
  for (const auto& [id, member] : kViewerChannels) {
    const std::vector<float>& from = frame.*codec::kReconstructedChannels[static_cast<std::size_t>(index_of(id))];
    (slot.*member).assign(from.begin(), from.end());
  }
  slot.jacobian.assign(frame.jacobian.begin(), frame.jacobian.end());
  used_[static_cast<std::size_t>(&slot - frames_.data())] = true;
}

double FrameTimeline::advance_render_clock(double now, double target) {
  const double period = config_.tick_period_s;
  if (!rendering_) {
    rendering_ = true;
    render_offset_s_ = target;
    last_render_tick_ = (now - render_offset_s_ - delay_s_) / period;
  } else {
    // Follow the estimate by running the render clock slightly fast or slow, so the picture never
    // jumps and never runs backwards; only a gross error (a new server clock) is jumped over.
    const double diff = target - render_offset_s_;
    const double dt = std::max(0.0, now - last_now_);
    if (std::fabs(diff) > config_.clock_snap_s) {
      render_offset_s_ = target;
      ++counters_.clock_snaps;
      last_render_tick_ = (now - render_offset_s_ - delay_s_) / period;
    } else {
      const double step = config_.max_clock_slew * dt;
      render_offset_s_ += std::clamp(diff, -step, step);
    }
  }
  const double render_tick = std::max(last_render_tick_, (now - render_offset_s_ - delay_s_) / period);
  if (starved_) counters_.stalled_s += std::max(0.0, now - last_now_);
  last_now_ = now;
  last_render_tick_ = render_tick;
  return render_tick;
}

std::pair<const TimelineFrame*, const TimelineFrame*> FrameTimeline::bracket(double render_tick) {
  const TimelineFrame* a = nullptr;  // newest at or before render_tick
  const TimelineFrame* b = nullptr;  // oldest after it
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (!used_[i]) continue;
    const TimelineFrame& f = frames_[i];
    if (static_cast<double>(f.tick) <= render_tick) {
      if (!a || f.tick > a->tick) a = &f;
    } else if (!b || f.tick < b->tick) {
      b = &f;
    }
  }
  // Frames older than a are never shown again: free their slots for reuse.
  if (a)
    for (std::size_t i = 0; i < frames_.size(); ++i)
      if (used_[i] && frames_[i].tick < a->tick) used_[i] = false;
  return {a, b};
}

TimelineSample FrameTimeline::sample(double now) {
  TimelineSample out;
  const auto offset = clock_.offset_s();
  if (!offset) return out;
  // More delay on a jittery link: the render clock's target moves back by the excess.
  const double target = *offset + (config_.adapt_to_jitter ? adaptive_delay_s() - delay_s_ : 0.0);
  const double render_tick = advance_render_clock(now, target);
  out.render_tick = render_tick;
  const auto [a, b] = bracket(render_tick);
  if (a && b) {
    out.status = TimelineSample::Status::interpolating;
    out.a = a;
    out.b = b;
    out.weight = static_cast<float>((render_tick - a->tick) / static_cast<double>(b->tick - a->tick));
    if (b->predicted)
      out.status = TimelineSample::Status::extrapolating;  // still starved
    else
      starved_ = false;
  } else if (a) {
    if (!starved_) ++counters_.stalls;
    starved_ = true;
    out.status = TimelineSample::Status::holding;
    out.a = out.b = a;
    // Starved: ask for the next tick's predicted frame and keep interpolating towards it.
    const auto want = static_cast<Tick>(std::floor(render_tick)) + 1;
    if (extrapolator_ && extrapolator_(want, predicted_)) {
      if (TimelineFrame* slot = slot_for(want); slot && slot != a) {
        fill(*slot, predicted_, want, now, true);
        ++counters_.frames_extrapolated;
        out.status = TimelineSample::Status::extrapolating;
        out.b = slot;
        out.weight = static_cast<float>((render_tick - a->tick) / static_cast<double>(want - a->tick));
      }
    }
  } else if (b) {
    out.status = TimelineSample::Status::waiting;
    out.a = out.b = b;
  }
  return out;
}

namespace {

// out = a + w (b - a); a alone when b lacks the channel.
void mix(float w, const std::vector<float>& a, const std::vector<float>& b, std::vector<float>& out) {
  out.resize(a.size());
  if (b.size() != a.size()) {
    std::copy(a.begin(), a.end(), out.begin());
    return;
  }
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] + w * (b[i] - a[i]);
}

}  // namespace

void FrameTimeline::blend(const TimelineSample& sample, std::vector<float>& height, std::vector<float>& slope_x,
                          std::vector<float>& slope_z) {
  if (!sample.a) return;
  mix(sample.weight, sample.a->height, sample.b->height, height);
  mix(sample.weight, sample.a->slope_x, sample.b->slope_x, slope_x);
  mix(sample.weight, sample.a->slope_z, sample.b->slope_z, slope_z);
}

void FrameTimeline::blend(const TimelineSample& sample, FrameChannels& out) {
  if (!sample.a) return;
  for (const auto& [id, member] : kViewerChannels) mix(sample.weight, sample.a->*member, sample.b->*member, out.*member);
  mix(sample.weight, sample.a->jacobian, sample.b->jacobian, out.jacobian);
}

}  // namespace ocean::client
