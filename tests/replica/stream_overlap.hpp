// How two recordings of one stream are compared: frame by frame along the same chain of
// baselines back to the same keyframe, byte for byte and in the heights they decode to
// (test_replica, test_timeline_fleet).
#pragma once

#include "frame_recorder.hpp"
#include "replica_pair.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace ocean::replica_test {

// The ticks from `tick` back to its keyframe through each frame's baseline; empty when the
// chain leaves the recording (then the frame's bytes depend on frames we never saw).
inline std::vector<std::uint32_t> lineage(const FrameRecorder& recorder, std::uint32_t tick) {
  std::vector<std::uint32_t> chain;
  for (;;) {
    auto it = recorder.frames().find(tick);
    if (it == recorder.frames().end() || !it->second.complete()) return {};
    chain.push_back(tick);
    if (it->second.key) return chain;
    tick = it->second.baseline;
  }
}

// Sleeps until `phase` (0..1) of the way between two frame ticks of a profile carrying every
// `step`-th tick, on the replicas' shared timeline: a Hello sent then is handled by both servers
// between the same two frame ticks, so the first key tick after it (whatever the servers' key
// policy) is the same for both.
inline void sleep_to_frame_phase(std::uint32_t step, double phase) {
  const double now_ms = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double period_ms = 1000.0 * step / kTickRateHz;
  const double position = std::fmod(now_ms - static_cast<double>(kEpochUnixMs), period_ms);
  double wait = phase * period_ms - position;
  if (wait < 0) wait += period_ms;
  std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(wait));
}

struct Overlap {
  std::size_t keys = 0, deltas = 0, chunks = 0, bytes = 0;
  std::size_t mismatched_chunks = 0;    // same (profile, tick, baseline, index, lineage), other bytes
  std::size_t other_lineage = 0;        // same tick in both, reached through different baselines
  std::size_t seas = 0, mismatched_seas = 0;  // of those frames, decoded by both; to other heights
  std::vector<std::string> mismatches;  // the first few, for the failure message

  Overlap& operator+=(const Overlap& o) {
    keys += o.keys;
    deltas += o.deltas;
    chunks += o.chunks;
    bytes += o.bytes;
    mismatched_chunks += o.mismatched_chunks;
    other_lineage += o.other_lineage;
    seas += o.seas;
    mismatched_seas += o.mismatched_seas;
    for (const std::string& m : o.mismatches)
      if (mismatches.size() < 5) mismatches.push_back(m);
    return *this;
  }
};

inline Overlap compare(const FrameRecorder& a, const FrameRecorder& b) {
  Overlap o;
  for (const auto& [tick, fa] : a.frames()) {
    auto found = b.frames().find(tick);
    if (found == b.frames().end()) continue;
    const RecordedFrame& fb = found->second;
    const std::vector<std::uint32_t> chain = lineage(a, tick), other_chain = lineage(b, tick);
    if (chain.empty() || other_chain.empty()) continue;  // still arriving
    if (chain != other_chain) {
      // A replica skipped a frame (a loaded machine): from here on the two hold other states.
      ++o.other_lineage;
      continue;
    }
    // Same tick, same baselines all the way back to the same keyframe tick.
    (fa.key ? o.keys : o.deltas)++;
    bool same = fa.profile_id == fb.profile_id && fa.count == fb.count;
    for (const auto& [index, payload] : fa.payloads) {
      auto other = fb.payloads.find(index);
      ++o.chunks;
      o.bytes += payload.size();
      if (other == fb.payloads.end() || other->second != payload) {
        same = false;
        ++o.mismatched_chunks;
      }
    }
    // The sea both decoded from it (the frames may carry no wave: the scenes announced decide).
    const auto sea_a = a.sea().find(tick), sea_b = b.sea().find(tick);
    if (sea_a != a.sea().end() && sea_b != b.sea().end()) {
      ++o.seas;
      if (sea_a->second != sea_b->second) {
        ++o.mismatched_seas;
        same = false;
      }
    }
    if (!same && o.mismatches.size() < 5)
      o.mismatches.push_back("tick " + std::to_string(tick) + (fa.key ? " key" : " delta from " + std::to_string(fa.baseline)) +
                             ": chunks " + std::to_string(fa.count) + " vs " + std::to_string(fb.count));
  }
  return o;
}

inline std::string describe(const FrameRecorder& r) {
  std::ostringstream out;
  out << r.frames().size() << " frames";
  if (r.first_key_tick()) out << ", first key at tick " << *r.first_key_tick();
  if (r.newest_tick()) out << ", newest tick " << *r.newest_tick();
  for (const std::string& fault : r.faults()) out << "; fault: " << fault;
  return out.str();
}

}  // namespace ocean::replica_test
