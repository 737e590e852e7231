// StreamFacts: the stream every client of a run gets, fixed by the first Welcome - its timing,
// grid and error bounds - and the tick arithmetic the load test does with it.
#pragma once

#include "tick.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "frame_recorder.hpp"
#include "frame_verdict.hpp"
#include "message_types.hpp"

namespace ocean::loadtest {

struct StreamFacts {
  double tick_period_s = 0.0;
  int tick_rate_hz = 0;
  Tick interval_ticks = 1;  // ticks between the stream's frames
  int grid = 0;
  std::vector<int> lattices;  // the frames' lattice sizes, in order (client::stream_lattices)
  bool choppy = false;  // the stream carries displacement and its derivatives: so must the truth
  ErrorBounds bounds{0.0, 0.0};
  double epoch_s = 0.0;  // unix seconds of tick 0
  double interpolation_delay_s = 0.0;

  static StreamFacts from(const protocol::Welcome& w) {
    StreamFacts f;
    f.tick_period_s = w.tick_period_s;
    f.tick_rate_hz = static_cast<int>(std::lround(1.0 / w.tick_period_s));
    if (w.stream.rate_hz)
      f.interval_ticks = std::max<Tick>(1, static_cast<Tick>(std::lround(f.tick_rate_hz / double(w.stream.rate_hz))));
    f.grid = w.stream.grid;
    f.lattices = client::stream_lattices(w.stream);
    f.choppy = w.stream.choppy;
    f.bounds = bounds_of(w.stream);
    f.epoch_s = static_cast<double>(w.epoch_unix_ms) / 1000.0;
    // FrameTimeline's default: three send intervals behind (Fiedler's snapshot interpolation).
    f.interpolation_delay_s = 3.0 * f.interval_ticks * f.tick_period_s;
    return f;
  }

  // The tick in progress at unix_s, modulo 2^32 as today's 32-bit wire tick carries it (a float
  // beyond the range of the cast's type would be undefined). The integrator widens ticks to 64 bits.
  Tick tick_at_unix(double unix_s) const {
    const double ticks = (unix_s - epoch_s) / tick_period_s;
    return ticks <= 0 ? 0u : static_cast<Tick>(std::floor(ticks));
  }
};

}  // namespace ocean::loadtest
