// Replica determinism: two ocean-server processes started from one config file, the second a
// second later, send byte-identical keyframes and deltas for the same tick and profile. A raw
// TCP client records each server's stream; once both streams start from a keyframe at the same
// tick, every frame both sent along the same chain of baselines must match byte for byte. (A
// replica starved of CPU may skip a frame; from there on its chain differs and nothing more is
// compared, so the test records a fresh pair of streams until enough frames were compared.)
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "frame_recorder.hpp"
#include "profile.hpp"
#include "replica_pair.hpp"

using namespace ocean;
using namespace ocean::replica_test;

namespace {

constexpr int kMaxAttempts = 12;
constexpr std::size_t kMinDeltas = 20;
constexpr double kAttemptS = 6.0;         // recording of one pair of streams, at most
constexpr double kProfileBudgetS = 12.0;  // all attempts of one profile, at most (a new one may start before)

// The ticks from `tick` back to its keyframe through each frame's baseline; empty when the
// chain leaves the recording (then the frame's bytes depend on frames we never saw).
std::vector<std::uint32_t> lineage(const FrameRecorder& recorder, std::uint32_t tick) {
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
void sleep_to_frame_phase(std::uint32_t step, double phase) {
  const double now_ms = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double period_ms = 1000.0 * step / kTickRateHz;
  const double position = std::fmod(now_ms - static_cast<double>(kEpochUnixMs), period_ms);
  double wait = phase * period_ms - position;
  if (wait < 0) wait += period_ms;
  std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(wait));
}

template <typename Done>
bool run_until(asio::io_context& io, Done done, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done() && std::chrono::steady_clock::now() < until) io.run_for(std::chrono::milliseconds(5));
  return done();
}

struct Overlap {
  std::size_t keys = 0, deltas = 0, chunks = 0, bytes = 0;
  std::size_t mismatched_chunks = 0;    // same (profile, tick, baseline, index, lineage), other bytes
  std::size_t other_lineage = 0;        // same tick in both, reached through different baselines
  std::vector<std::string> mismatches;  // the first few, for the failure message

  Overlap& operator+=(const Overlap& o) {
    keys += o.keys;
    deltas += o.deltas;
    chunks += o.chunks;
    bytes += o.bytes;
    mismatched_chunks += o.mismatched_chunks;
    other_lineage += o.other_lineage;
    for (const std::string& m : o.mismatches)
      if (mismatches.size() < 5) mismatches.push_back(m);
    return *this;
  }
};

Overlap compare(const FrameRecorder& a, const FrameRecorder& b) {
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
    if (!same && o.mismatches.size() < 5)
      o.mismatches.push_back("tick " + std::to_string(tick) + (fa.key ? " key" : " delta from " + std::to_string(fa.baseline)) +
                             ": chunks " + std::to_string(fa.count) + " vs " + std::to_string(fb.count));
  }
  return o;
}

std::string describe(const FrameRecorder& r) {
  std::ostringstream out;
  out << r.frames().size() << " frames";
  if (r.first_key_tick()) out << ", first key at tick " << *r.first_key_tick();
  if (r.newest_tick()) out << ", newest tick " << *r.newest_tick();
  for (const std::string& fault : r.faults()) out << "; fault: " << fault;
  return out.str();
}

// Records both replicas' streams of one profile, as often as needed, until the frames compared
// (identical lineage in both) hold a keyframe and kMinDeltas deltas; all must be byte-identical.
void check_profile(ReplicaPair& pair, const Profile& profile) {
  const std::uint32_t step = kTickRateHz / profile.rate_hz;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kProfileBudgetS);
  Overlap total;
  std::vector<std::string> attempts;
  const auto enough = [&](const Overlap& more) { return total.keys + more.keys >= 1 && total.deltas + more.deltas >= kMinDeltas; };
  for (int attempt = 1; attempt <= kMaxAttempts && !enough({}) && std::chrono::steady_clock::now() < deadline; ++attempt) {
    asio::io_context io;
    FrameRecorder a(io, pair.port(0), profile.id), b(io, pair.port(1), profile.id);
    sleep_to_frame_phase(step, 0.5);
    a.send_hello();
    b.send_hello();
    INFO(pair.logs());
    REQUIRE(run_until(io, [&] { return a.first_key_tick() && b.first_key_tick(); }, 10.0));
    if (*a.first_key_tick() != *b.first_key_tick()) {
      // A Hello straddled a key tick: these two streams share no frame. Try again.
      attempts.push_back("keys at ticks " + std::to_string(*a.first_key_tick()) + " and " +
                         std::to_string(*b.first_key_tick()));
      continue;
    }
    // Until enough is compared, or the streams diverged (then nothing more can be compared).
    Overlap o;
    run_until(io, [&] {
      o = compare(a, b);
      return enough(o) || o.other_lineage > 0;
    }, kAttemptS);
    a.close();
    b.close();
    o = compare(a, b);
    attempts.push_back("keys at tick " + std::to_string(*a.first_key_tick()) + ": " + std::to_string(o.keys) + " key + " +
                       std::to_string(o.deltas) + " deltas compared, " + std::to_string(o.other_lineage) +
                       " frames reached by other baselines; A " + describe(a) + "; B " + describe(b));
    INFO(profile.name << " attempt " << attempt << ": " << attempts.back());
    CHECK(a.faults().empty());
    CHECK(b.faults().empty());

    // Both replicas describe one stream: same scene, stream parameters, epoch and tick period.
    REQUIRE(a.welcome());
    REQUIRE(b.welcome());
    CHECK(a.welcome()->stream == b.welcome()->stream);
    CHECK(a.welcome()->scene == b.welcome()->scene);
    CHECK(a.welcome()->stream.profile_id == profile.id);
    CHECK(a.welcome()->epoch_unix_ms == kEpochUnixMs);
    CHECK(b.welcome()->epoch_unix_ms == kEpochUnixMs);
    CHECK(a.welcome()->tick_period_s == b.welcome()->tick_period_s);
    CHECK(a.welcome()->session_id != b.welcome()->session_id);
    total += o;
  }
  std::string tried, first_mismatches;
  for (const std::string& t : attempts) tried += "\n  " + t;
  for (const std::string& m : total.mismatches) first_mismatches += m + "; ";
  INFO(profile.name << ": " << attempts.size() << " attempt(s):" << tried);
  INFO("compared: " << total.keys << " keys, " << total.deltas << " deltas, " << total.chunks << " chunks, " << total.bytes
                    << " payload bytes; mismatches: " << first_mismatches);
  CHECK(total.mismatched_chunks == 0);
  CHECK(total.keys >= 1);
  CHECK(total.deltas >= kMinDeltas);
  WARN(profile.name << ": " << total.keys << " key(s) + " << total.deltas << " deltas compared (" << total.chunks
                    << " chunks, " << total.bytes << " bytes), " << total.mismatched_chunks << " chunks differ; "
                    << attempts.size() << " attempt(s)");
}

}  // namespace

TEST_CASE("replicas send byte-identical frames", "[replica]") {
  ReplicaPair pair(1.0);
  for (const char* name : {"mobile", "lite"}) {
    const Profile* profile = find_profile(name);
    REQUIRE(profile);
    check_profile(pair, *profile);
  }
}
