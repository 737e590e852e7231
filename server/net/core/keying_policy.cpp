#include "keying_policy.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ocean::server {

KeyingPolicy::KeyingPolicy(const KeyingOptions& options, int tick_rate_hz, double now_s)
    : options_(options),
      tick_rate_hz_(tick_rate_hz),
      key_budget_(options.key_bytes_per_s, std::max(1.0, 0.5 * options.key_bytes_per_s), now_s) {}

bool KeyingPolicy::is_key_tick(const KeyedStream& stream, Tick tick) const {
  const auto frames = std::max<long>(1, std::lround(options_.key_period_s * stream.rate_hz));
  return tick % (static_cast<Tick>(stream.tick_step) * static_cast<Tick>(frames)) == 0;
}

// A root's deltas cost a synthesis of the profile's grid each frame: a profile's roots together
// may cost root_samples_per_tick grid samples a tick.
std::size_t KeyingPolicy::root_budget(const KeyedStream& stream) const {
  const double grid = stream.grid;
  const double per_tick = grid * grid / static_cast<double>(stream.tick_step);
  const double fits = std::floor(options_.root_samples_per_tick / per_tick);
  return std::max<std::size_t>(2, static_cast<std::size_t>(std::clamp(fits, 0.0, 1e6)));
}

std::size_t KeyingPolicy::root_cap(const KeyedStream& stream) const {
  return std::min(options_.max_roots, root_budget(stream));
}

// The key budget is in bytes: a modeled mobile key (tens of bytes) costs the links and the
// server next to nothing, a desktop key with coefficients thousands of times more.
bool KeyingPolicy::take_key(double key_bytes, double now_s) {
  return key_budget_.try_take_leaving(std::min(key_bytes, key_budget_.burst()), 0.0, now_s);
}

// Merged sessions must all take this tick's key, or they would only scatter into new roots. The
// largest root is never merged (re-keying most clients to absorb a few would be a key storm),
// and a session pays at most one extra key per root_merge_age_s. Where one more root would exceed
// the profile's root budget (desktop), the joiners wait for a key tick with room; cheap roots
// (mobile) let them in and the merges catch up.
RootPlan KeyingPolicy::plan_roots(const KeyedStream& stream, const std::map<Tick, std::size_t>& roots,
                                  std::size_t waiting, Tick tick, const std::function<double()>& key_bytes_of,
                                  double now_s) {
  // Between joins the roots are consolidated to two (the largest and the one merged onto this
  // key), so a quiet server pays two encodes a tick, not the cap's.
  const std::size_t cap = waiting > 0 ? root_cap(stream) : std::min<std::size_t>(2, root_cap(stream));
  const std::size_t budget = root_budget(stream);
  const auto room = [&](std::size_t roots_after) { return waiting == 0 || roots_after <= budget; };
  RootPlan plan;
  if (roots.size() + (waiting > 0 ? 1 : 0) <= cap) return plan;
  Tick largest = 0;
  std::size_t largest_size = 0;
  for (const auto& [root, members] : roots)
    if (members > largest_size) {
      largest = root;
      largest_size = members;
    }
  const double min_age_ticks = options_.root_merge_age_s * tick_rate_hz_;
  std::vector<std::pair<std::size_t, Tick>> old;  // (sessions, root)
  for (const auto& [root, members] : roots)
    if (root != largest && static_cast<double>(tick - root) >= min_age_ticks) old.emplace_back(members, root);
  // After merging m roots there are roots - m + 1. Without joiners, merging one lowers nothing.
  const std::size_t least = waiting > 0 ? 1 : 2;
  std::size_t merge = std::min(old.size(), roots.size() + 1 - cap);
  const bool enter_anyway = room(roots.size() + 1);  // the joiners start their root, merge or not
  plan.enter = enter_anyway;
  if (merge < least) return plan;
  std::sort(old.begin(), old.end());
  // The budget pays the waiting joiners' keys first, unless they wait for this merge: then it
  // goes first and must leave one joiner's key.
  const double key_bytes = key_bytes_of();
  const double reserve = static_cast<double>(enter_anyway ? waiting : 1) * key_bytes;
  for (; merge >= least; --merge) {
    std::size_t sessions = 0;
    for (std::size_t i = 0; i < merge; ++i) sessions += old[i].first;
    if (key_budget_.try_take_leaving(static_cast<double>(sessions) * key_bytes, reserve, now_s)) break;
  }
  // A root whose keys the budget's burst can never hold (large explicit keys, a small budget)
  // cannot be merged: then the joiners start a root beyond the cap rather than wait for good.
  if (merge < least) {
    plan.enter = enter_anyway || static_cast<double>(old.front().first) * key_bytes + reserve > key_budget_.burst();
    return plan;
  }
  for (std::size_t i = 0; i < merge; ++i) plan.merge.push_back(old[i].second);
  plan.enter = room(roots.size() + 1 - merge);
  return plan;
}

}  // namespace ocean::server
