// FrameTimeline: the client's jitter buffer and snapshot interpolation (Fiedler). Holds recent
// reconstructed frames by tick in reused buffers, estimates the server tick clock from arrivals,
// and for a render time names the two frames to blend, a fixed delay behind. Pure: time is an argument.
#pragma once

#include "tick.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "arrival_clock.hpp"
#include "frame_channels.hpp"
#include "frame_reconstruction.hpp"

#include <algorithm>

namespace ocean::client {

struct FrameTimelineConfig {
  double tick_period_s = 1.0 / 30.0;
  double send_interval_s = 0.0;          // time between frames the server sends; 0 = tick_period_s
  double delay_intervals = 3.0;          // render this many send intervals behind the newest frame
  double interpolation_delay_s = 0.0;    // if > 0, used instead of delay_intervals * send interval
  // A jittery link gets more delay: at least the clock's jitter (ArrivalClock::jitter_s) plus one
  // send interval, and on a stream a retransmission's cover (set_stream_rtt_s), reached by
  // slewing like the clock itself.
  bool adapt_to_jitter = true;
  std::size_t capacity = 16;             // frames held; the oldest goes first
  std::size_t clock_window = 64;         // arrivals the clock minimum is taken over
  double max_clock_slew = 0.02;          // the render clock runs at most 2% fast or slow to follow the estimate
  double clock_snap_s = 1.0;             // an estimate this far off is jumped to (reconnect, server restart)
};

// A frame held: the channels a viewer keeps (FrameChannels), by tick.
struct TimelineFrame : FrameChannels {
  Tick tick = 0;
  double arrival_s = 0.0;
  bool predicted = false;  // made by the extrapolator; a real frame of its tick replaces it
};


struct TimelineSample {
  enum class Status : std::uint8_t {
    empty,          // no frame yet
    waiting,        // render time is before the oldest frame: showing it
    interpolating,  // between a and b
    holding,        // starved: render time is past the newest frame, showing it (a stall)
    extrapolating,  // starved, but b is a predicted frame: the sea keeps moving (a stall too)
  };
  Status status = Status::empty;
  const TimelineFrame* a = nullptr;  // blend a * (1 - weight) + b * weight; b == a when not interpolating
  const TimelineFrame* b = nullptr;
  float weight = 0.0f;
  double render_tick = 0.0;  // where on the server's tick axis this render time falls
};

struct TimelineCounters {
  std::uint64_t frames_pushed = 0;
  std::uint64_t frames_late = 0;       // arrived after the render time had passed their tick
  std::uint64_t frames_discarded = 0;  // duplicates, or older than everything held with no room
  std::uint64_t stalls = 0;            // times the render time overtook the newest frame
  std::uint64_t frames_extrapolated = 0;
  double stalled_s = 0.0;              // render time spent holding
  std::uint64_t clock_snaps = 0;
};

class FrameTimeline {
 public:
  // Fills out with the frame of a tick no frame has arrived for yet (e.g. FramePredictor); false
  // when it cannot.
  using Extrapolator = std::function<bool(Tick tick, codec::ReconstructedFrame& out)>;

  explicit FrameTimeline(FrameTimelineConfig config = {});

  // Without one, a starved timeline holds its newest frame.
  void set_extrapolator(Extrapolator extrapolator) { extrapolator_ = std::move(extrapolator); }

  // Copies the frame into a reused buffer (no allocation once the buffers have grown).
  void push(const codec::ReconstructedFrame& frame, Tick tick, double arrival_s);
  // What to show at client time now; now must not decrease between calls. The pointers stay
  // valid until the next push() or sample().
  TimelineSample sample(double now);
  // out = a * (1 - weight) + b * weight for every channel the frames hold (resized to fit).
  static void blend(const TimelineSample& sample, std::vector<float>& height, std::vector<float>& slope_x,
                    std::vector<float>& slope_z);
  static void blend(const TimelineSample& sample, FrameChannels& out);

  // The round trip of the stream the frames come on (TCP, WebSocket); 0 while they come as
  // datagrams. Loss below a stream loses no frame but holds it: a lost segment is resent once a
  // later one is acknowledged and a quarter round trip has passed (RACK, RFC 8985), so it and all
  // sent after it come about 1.25 round trips plus a send interval late. The jitter window learns
  // that only by stalling on it, and forgets it before the next (one every few seconds at 1 %
  // loss), so a stream's buffer covers one retransmission from the start instead.
  void set_stream_rtt_s(double rtt_s) { stream_rtt_s_ = rtt_s; }
  double interpolation_delay_s() const { return delay_s_; }
  // The delay the link asks for now (>= interpolation_delay_s()).
  double adaptive_delay_s() const { return adaptive_delay(clock_, delay_s_, send_interval_s_, stream_rtt_s_); }
  // One send interval to interpolate towards the next frame on top of the jitter seen, or on a
  // stream of one retransmission's lateness, whichever is more (a Ping's round trip already holds
  // the link's queueing; adding the jitter window would count each stall twice).
  static double adaptive_delay(const ArrivalClock& clock, double base_delay_s, double send_interval_s,
                               double stream_rtt_s = 0.0) {
    const double lateness = retransmission_lateness_s(stream_rtt_s, send_interval_s);
    return std::max({base_delay_s, clock.jitter_s() + send_interval_s, lateness > 0.0 ? lateness + send_interval_s : 0.0});
  }
  // How late a frame held behind one retransmission comes (0 without a stream).
  static double retransmission_lateness_s(double stream_rtt_s, double send_interval_s) {
    return stream_rtt_s > 0.0 ? 1.25 * stream_rtt_s + send_interval_s : 0.0;
  }
  const TimelineCounters& counters() const { return counters_; }
  const ArrivalClock& clock() const { return clock_; }
  std::size_t frames_held() const;
  void clear();

 private:
  // The render tick at `now`, the render clock slewed towards `target` (its offset estimate).
  double advance_render_clock(double now, double target);
  // The newest frame at or before render_tick and the oldest after it; frees older slots.
  std::pair<const TimelineFrame*, const TimelineFrame*> bracket(double render_tick);
  TimelineFrame* slot_for(Tick tick);
  void fill(TimelineFrame& slot, const codec::ReconstructedFrame& frame, Tick tick, double arrival_s,
            bool predicted);

  FrameTimelineConfig config_;
  Extrapolator extrapolator_;
  codec::ReconstructedFrame predicted_;  // the extrapolator's scratch
  double delay_s_;
  double send_interval_s_;
  double stream_rtt_s_ = 0.0;
  ArrivalClock clock_;
  std::vector<TimelineFrame> frames_;
  std::vector<bool> used_;
  TimelineCounters counters_;
  bool rendering_ = false;
  double render_offset_s_ = 0.0;  // the clock offset the render time follows, slewed towards clock_
  double last_now_ = 0.0;
  double last_render_tick_ = 0.0;
  bool starved_ = false;
};

}  // namespace ocean::client
