#include "decode_memo.hpp"

#include "common/fnv1a.hpp"

#include <algorithm>

namespace ocean::codec {
namespace {

std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) { return common::fnv1a(bytes.data(), bytes.size()); }

std::uint64_t key_hash(Tick tick, const DecodeMemo::Payloads& chunks) {
  std::uint64_t h = fnv1a({}) ^ tick;
  for (const auto& c : chunks) h = (h * common::kFnvPrime) ^ fnv1a(c);
  return h;
}

std::uint64_t key_hash(Tick tick, std::span<const std::uint8_t> single) {
  return ((fnv1a({}) ^ tick) * common::kFnvPrime) ^ fnv1a(single);
}

// Interning only needs equal states to collide: a word at a time (hash_state, the documented
// fingerprint, goes byte by byte and cost a load test 7 % of its time).
std::uint64_t intern_hash(const ModalState& s) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const auto* v : {&s.prev.re, &s.prev.im, &s.cur.re, &s.cur.im})
    for (const std::int64_t x : *v) h = (h ^ static_cast<std::uint64_t>(x)) * 0xBF58476D1CE4E5B9ull + (h >> 31);
  return h;
}

}  // namespace

std::size_t DecodeMemo::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = k.payload_hash ^ (reinterpret_cast<std::uintptr_t>(k.baseline) * 0x9E3779B97F4A7C15ull);
  h ^= (h >> 29) ^ (k.tick * 0xBF58476D1CE4E5B9ull);
  return static_cast<std::size_t>(h ^ (h >> 32));
}

DecodeMemo::Result DecodeMemo::shared_result(State state, ReconstructedFrame&& frame) {
  frame.shared_id = ++frame_ids_;
  return Result{std::move(state), std::make_shared<const ReconstructedFrame>(std::move(frame))};
}

DecodeMemo::DecodeMemo(const StreamConfig& config, std::uint32_t window_ticks) : config_(config), window_(window_ticks) {}

void DecodeMemo::saw_tick(Tick tick) {
  if (tick <= newest_) return;
  newest_ = tick;
  if (newest_ < window_) return;
  const Tick oldest = newest_ - window_;
  while (!states_.empty() && states_.begin()->first < oldest) states_.erase(states_.begin());
  std::erase_if(deltas_, [oldest](const auto& item) { return item.first.tick < oldest; });
  std::erase_if(keys_, [oldest](const auto& item) { return item.second.tick < oldest; });
  std::erase_if(advanced_, [oldest](const auto& item) { return item.second.from < oldest; });
}

void DecodeMemo::advance(const State& baseline, Tick from, Tick to, const SceneTimeline& scenes, ModalState& out) {
  Advanced& a = advanced_.try_emplace(baseline.get(), Advanced{baseline, from, {}}).first->second;
  out = a.state.advance(*baseline, from, to, scenes);
}

const DecodeMemo::Result* DecodeMemo::find_key(Tick tick, const Payloads& chunks) {
  const auto [begin, end] = keys_.equal_range(key_hash(tick, chunks));
  for (auto it = begin; it != end; ++it)
    if (it->second.tick == tick && it->second.chunks == chunks) {
      ++counts_.hits;
      return &it->second.result;
    }
  ++counts_.misses;
  return nullptr;
}

const DecodeMemo::Result* DecodeMemo::find_key(Tick tick, std::span<const std::uint8_t> payload) {
  const auto [begin, end] = keys_.equal_range(key_hash(tick, payload));
  for (auto it = begin; it != end; ++it) {
    const KeyEntry& e = it->second;
    if (e.tick == tick && e.chunks.size() == 1 && std::equal(e.chunks[0].begin(), e.chunks[0].end(), payload.begin(), payload.end())) {
      ++counts_.hits;
      return &e.result;
    }
  }
  return nullptr;
}

const DecodeMemo::Result& DecodeMemo::remember_key(Tick tick, const Payloads& chunks, State state,
                                                   ReconstructedFrame&& frame) {
  saw_tick(tick);
  KeyEntry entry{tick, chunks, shared_result(std::move(state), std::move(frame))};
  return keys_.emplace(key_hash(tick, chunks), std::move(entry))->second.result;
}

DecodeMemo::State DecodeMemo::intern(Tick tick, ModalState&& state) {
  saw_tick(tick);
  auto& same_tick = states_[tick];
  const std::uint64_t hash = intern_hash(state);
  const auto [begin, end] = same_tick.equal_range(hash);
  for (auto it = begin; it != end; ++it) {
    if (*it->second == state) {
      ++counts_.intern_hits;
      return it->second;
    }
  }
  ++counts_.interned;
  State shared = std::make_shared<const ModalState>(std::move(state));
  same_tick.emplace(hash, shared);
  return shared;
}

const DecodeMemo::Result* DecodeMemo::find(const State& baseline, Tick tick, std::span<const std::uint8_t> payload) {
  const auto found = deltas_.find(Key{baseline.get(), tick, fnv1a(payload)});
  if (found != deltas_.end()) {
    for (const Entry& e : found->second) {
      if (std::equal(e.payload.begin(), e.payload.end(), payload.begin(), payload.end())) {
        ++counts_.hits;
        return &e.result;
      }
    }
  }
  ++counts_.misses;
  return nullptr;
}

const DecodeMemo::Result& DecodeMemo::remember(const State& baseline, Tick tick, std::span<const std::uint8_t> payload,
                                               State state, ReconstructedFrame&& frame) {
  saw_tick(tick);
  Entry entry{baseline, std::vector<std::uint8_t>(payload.begin(), payload.end()),
              shared_result(std::move(state), std::move(frame))};
  auto& bucket = deltas_[Key{baseline.get(), tick, fnv1a(payload)}];
  bucket.push_back(std::move(entry));
  return bucket.back().result;
}

}  // namespace ocean::codec
