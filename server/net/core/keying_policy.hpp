// KeyingPolicy: when a profile's stream may send keys, and how many key roots it keeps. Sessions
// keyed at different ticks hold different states for good (a key is lossy), so every root costs
// its own delta encodes each tick (README-server.md "Fan-out"). The policy decides from counts
// and times alone - which ticks are key ticks, whether the server-wide key budget pays for a key,
// which roots are merged onto this key tick's - and the session core applies it to its sessions.
#pragma once

#include "tick.hpp"
#include "token_bucket.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace ocean::server {

struct KeyingOptions {
  double key_period_s = 0.5;           // keys only on a grid of this period
  std::size_t max_roots = 4;           // at most this many roots per profile...
  double root_samples_per_tick = 131072.0;  // ...or as many as synthesize this many samples a tick (>= 2)
  double root_merge_age_s = 2.0;       // a root this young is never merged
  double key_bytes_per_s = 2'000'000.0;  // every key of the server (burst: half a second of it)
};

// One profile's stream as the policy sees it.
struct KeyedStream {
  int grid = 0;               // samples per side of a root's synthesis
  std::uint32_t tick_step = 1;  // server ticks per frame
  int rate_hz = 0;            // frames per second
};

// What a key tick does with a profile's roots: the roots keyed again onto this tick's key, and
// whether the sessions waiting for a key start their root now (else they wait for a key tick
// with room).
struct RootPlan {
  std::vector<Tick> merge;
  bool enter = true;
};

class KeyingPolicy {
 public:
  KeyingPolicy(const KeyingOptions& options, int tick_rate_hz, double now_s);

  bool is_key_tick(const KeyedStream& stream, Tick tick) const;
  // The roots whose synthesis the per-tick sample budget pays for (at least 2), and the cap the
  // merges keep (that, at most max_roots).
  std::size_t root_budget(const KeyedStream& stream) const;
  std::size_t root_cap(const KeyedStream& stream) const;
  // Takes a key's bytes from the server-wide budget (a key larger than the burst waits for a full
  // bucket rather than forever); false when it must wait.
  bool take_key(double key_bytes, double now_s);

  // roots: root tick -> sessions on it; waiting: sessions that need a key to show anything.
  // Beyond the cap the smallest roots old enough are merged, never the largest, as many as it
  // takes and as the key budget pays for now after the waiting sessions' keys (the budget is
  // charged for the merged sessions' keys). key_bytes is asked only when a merge is weighed:
  // it encodes this tick's key.
  RootPlan plan_roots(const KeyedStream& stream, const std::map<Tick, std::size_t>& roots, std::size_t waiting,
                      Tick tick, const std::function<double()>& key_bytes, double now_s);

 private:
  KeyingOptions options_;
  int tick_rate_hz_;
  TokenBucket key_budget_;
};

}  // namespace ocean::server
