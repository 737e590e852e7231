// SharedTimeline: a FrameTimeline behind a mutex for the viewer - the network thread pushes frames
// as they complete, the render thread blends the frame of its render time into its own buffers.
// The one place in this library where two threads meet; everything else is single-threaded.
#pragma once

#include "tick.hpp"

#include <mutex>
#include <vector>

#include "frame_timeline.hpp"

namespace ocean::client {

struct RenderedFrame {
  TimelineSample::Status status = TimelineSample::Status::empty;
  double render_tick = 0.0;
  Tick tick_a = 0, tick_b = 0;
  float weight = 0.0f;
};

class SharedTimeline {
 public:
  explicit SharedTimeline(FrameTimelineConfig config = {}) : timeline_(config) {}

  // Starts over with a new configuration (e.g. the tick period of a new Welcome).
  void reset(FrameTimelineConfig config) {
    std::lock_guard lock(mutex_);
    timeline_ = FrameTimeline(config);
  }

  // stream_rtt_s: FrameTimeline::set_stream_rtt_s, as the session knows it at this arrival.
  void push(const codec::ReconstructedFrame& frame, Tick tick, double arrival_s, double stream_rtt_s = 0.0) {
    std::lock_guard lock(mutex_);
    timeline_.set_stream_rtt_s(stream_rtt_s);
    timeline_.push(frame, tick, arrival_s);
  }

  // Leaves the buffers untouched while the status is empty.
  RenderedFrame render(double now, std::vector<float>& height, std::vector<float>& slope_x,
                       std::vector<float>& slope_z) {
    std::lock_guard lock(mutex_);
    const TimelineSample s = timeline_.sample(now);
    FrameTimeline::blend(s, height, slope_x, slope_z);
    RenderedFrame out{s.status, s.render_tick, 0, 0, s.weight};
    if (s.a) out.tick_a = s.a->tick, out.tick_b = s.b->tick;
    return out;
  }

  RenderedFrame render(double now, FrameChannels& out) {
    std::lock_guard lock(mutex_);
    const TimelineSample s = timeline_.sample(now);
    FrameTimeline::blend(s, out);
    RenderedFrame r{s.status, s.render_tick, 0, 0, s.weight};
    if (s.a) r.tick_a = s.a->tick, r.tick_b = s.b->tick;
    return r;
  }

  TimelineCounters counters() const {
    std::lock_guard lock(mutex_);
    return timeline_.counters();
  }

 private:
  mutable std::mutex mutex_;
  FrameTimeline timeline_;
};

}  // namespace ocean::client
