// Replica determinism: two ocean-server processes started from one config file, the second a
// second later, send byte-identical keyframes and deltas for the same tick and profile. A raw
// TCP client records each server's stream; once both streams start from a keyframe at the same
// tick, every frame both sent along the same chain of baselines must match byte for byte. (A
// replica starved of CPU may skip a frame; from there on its chain differs and nothing more is
// compared, so the test records a fresh pair of streams until enough frames were compared.)
// The same check runs against replicas started elsewhere (a hidden test case below): the
// container stage compares the pods of deploy/k8s this way.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <optional>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>
#include <atomic>
#include <sys/wait.h>

#include "frame_recorder.hpp"
#include "profile.hpp"
#include "replica_pair.hpp"
#include "stream_overlap.hpp"
#include "run_until.hpp"

using namespace ocean;
using namespace ocean::replica_test;
using ocean::test::run_until;

namespace {

constexpr int kMaxAttempts = 12;
constexpr std::size_t kMinDeltas = 20;
constexpr double kAttemptS = 6.0;         // recording of one pair of streams, at most
constexpr double kProfileBudgetS = 12.0;  // all attempts of one profile, at most (a new one may start before)

// The command OCEAN_REPLICA_CHANGE names, run once (the container stage: an admin change through
// one replica of a fleet following one timeline).
const char* const change_command = std::getenv("OCEAN_REPLICA_CHANGE");
bool change_made = false;

// After OCEAN_REPLICA_CHANGE: it succeeded, every replica announced the same change, and frames
// from its tick on were compared along one lineage (byte and sea checks as every other frame).
void check_change(const std::vector<std::unique_ptr<FrameRecorder>>& recorders, int status) {
  INFO("OCEAN_REPLICA_CHANGE: " << change_command);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  const FrameRecorder& a = *recorders.front();
  REQUIRE(a.scene_updates().size() == 1);
  const Tick effective = a.scene_updates().front().effective_tick;
  for (const auto& r : recorders) {
    REQUIRE(r->scene_updates().size() == 1);
    CHECK(r->scene_updates().front() == a.scene_updates().front());
    std::size_t after = 0;
    for (const auto& [tick, frame] : a.frames())
      if (tick >= effective && !lineage(a, tick).empty() && lineage(a, tick) == lineage(*r, tick)) ++after;
    CHECK(after >= 10);
  }
  std::printf("[replica] a change through a replica (%s) took effect on all %zu at tick %llu\n", change_command,
              recorders.size(), static_cast<unsigned long long>(effective));
}

// Where the replicas under test listen, what their logs say, and the epoch they must all
// announce (none: whatever it is, as long as they agree).
struct Replicas {
  std::vector<asio::ip::tcp::endpoint> servers;
  std::function<std::string()> logs;
  std::optional<std::int64_t> epoch_unix_ms;
  // Compare the heights the frames decode to as well (the pods of the container stage, across a
  // timeline change); the processes here compare bytes only, as many attempts as a busy
  // sanitizer build needs.
  bool decode = false;
};

// Records every replica's stream of one profile, as often as needed, until the frames compared
// (identical lineage in the first replica and each other one) hold a keyframe and kMinDeltas
// deltas; all must be byte-identical.
void check_profile(const Replicas& replicas, const Profile& profile) {
  const std::uint32_t step = kTickRateHz / profile.rate_hz;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kProfileBudgetS);
  Overlap total;
  std::vector<std::string> attempts;
  const auto enough = [&](const Overlap& more) { return total.keys + more.keys >= 1 && total.deltas + more.deltas >= kMinDeltas; };
  for (int attempt = 1; attempt <= kMaxAttempts && !enough({}) && std::chrono::steady_clock::now() < deadline; ++attempt) {
    asio::io_context io;
    std::vector<std::unique_ptr<FrameRecorder>> recorders;
    for (const auto& server : replicas.servers)
      recorders.push_back(std::make_unique<FrameRecorder>(io, server, profile.id, replicas.decode));
    const FrameRecorder& a = *recorders.front();
    sleep_to_frame_phase(step, 0.5);
    for (auto& r : recorders) r->send_hello();
    INFO(replicas.logs());
    const auto all_keyed = [&] {
      return std::all_of(recorders.begin(), recorders.end(), [](const auto& r) { return r->first_key_tick().has_value(); });
    };
    REQUIRE(run_until(io, all_keyed, 10.0));
    const bool same_key = std::all_of(recorders.begin(), recorders.end(),
                                      [&](const auto& r) { return *r->first_key_tick() == *a.first_key_tick(); });
    if (!same_key) {
      // A Hello straddled a key tick: these streams share no frame. Try again.
      std::string ticks;
      for (const auto& r : recorders) ticks += " " + std::to_string(*r->first_key_tick());
      attempts.push_back("keys at ticks" + ticks);
      continue;
    }
    // Each replica against the first, until enough is compared or one diverged (then nothing
    // more can be compared); what counts is the least any pair compared.
    const auto overlap = [&] {
      Overlap least, all;
      for (std::size_t i = 1; i < recorders.size(); ++i) {
        const Overlap o = compare(a, *recorders[i]);
        if (i == 1 || o.keys + o.deltas < least.keys + least.deltas) least = o;
        all += o;
      }
      least.mismatched_chunks = all.mismatched_chunks;
      least.mismatched_seas = all.mismatched_seas;
      least.other_lineage = all.other_lineage;
      least.mismatches = all.mismatches;
      return least;
    };
    // OCEAN_REPLICA_CHANGE (a command: ocean-admin through one replica), once per run, in the first
    // keyed recording: it records on until a second past the change's tick on every replica.
    const bool changing = change_command && !change_made;
    std::atomic<int> change_status{-1};
    std::optional<std::thread> change;
    if (changing) {
      change_made = true;
      change.emplace([&] { change_status = std::system(change_command); });
    }
    const auto past_change = [&] {
      if (!changing) return true;
      if (a.scene_updates().empty()) return false;
      const Tick effective = a.scene_updates().front().effective_tick;
      return std::all_of(recorders.begin(), recorders.end(),
                         [&](const auto& r) { return r->newest_tick() && *r->newest_tick() >= effective + kTickRateHz; });
    };
    Overlap o;
    run_until(io, [&] {
      o = overlap();
      return (enough(o) && past_change()) || o.other_lineage > 0;
    }, kAttemptS);
    if (change) change->join();
    if (changing) check_change(recorders, change_status.load());
    for (auto& r : recorders) r->close();
    o = overlap();
    std::string described;
    for (std::size_t i = 0; i < recorders.size(); ++i) described += "; replica " + std::to_string(i) + ": " + describe(*recorders[i]);
    attempts.push_back("keys at tick " + std::to_string(*a.first_key_tick()) + ": " + std::to_string(o.keys) + " key + " +
                       std::to_string(o.deltas) + " deltas compared, " + std::to_string(o.other_lineage) +
                       " frames reached by other baselines" + described);
    INFO(profile.name << " attempt " << attempt << ": " << attempts.back());
    // All replicas describe one stream: same scene, stream parameters, epoch and tick period.
    for (const auto& r : recorders) {
      CHECK(r->faults().empty());
      REQUIRE(r->welcome());
      CHECK(r->welcome()->stream == a.welcome()->stream);
      CHECK(r->welcome()->scene == a.welcome()->scene);
      CHECK(r->welcome()->stream.profile_id == profile.id);
      CHECK(r->welcome()->epoch_unix_ms == replicas.epoch_unix_ms.value_or(a.welcome()->epoch_unix_ms));
      CHECK(r->welcome()->tick_period_s == a.welcome()->tick_period_s);
      if (r.get() != &a) CHECK(r->welcome()->session_id != a.welcome()->session_id);
    }
    total += o;
  }
  std::string tried, first_mismatches;
  for (const std::string& t : attempts) tried += "\n  " + t;
  for (const std::string& m : total.mismatches) first_mismatches += m + "; ";
  INFO(profile.name << ": " << attempts.size() << " attempt(s):" << tried);
  INFO("compared: " << total.keys << " keys, " << total.deltas << " deltas, " << total.chunks << " chunks, " << total.bytes
                    << " payload bytes; mismatches: " << first_mismatches);
  CHECK(total.mismatched_chunks == 0);
  CHECK(total.mismatched_seas == 0);
  if (replicas.decode) CHECK(total.seas + 3 >= total.keys + total.deltas);
  CHECK(total.keys >= 1);
  CHECK(total.deltas >= kMinDeltas);
  std::printf("[replica] %.*s: %zu replicas, %zu key(s) + %zu deltas compared with the first (%zu chunks, %zu bytes), "
              "%zu chunks differ; %zu decoded by both, %zu to other heights; %zu attempt(s)\n",
              static_cast<int>(profile.name.size()), profile.name.data(), replicas.servers.size(), total.keys, total.deltas, total.chunks, total.bytes,
              total.mismatched_chunks, total.seas, total.mismatched_seas, attempts.size());
  std::fflush(stdout);
}

// "HOST:PORT,HOST:PORT,..." (numeric addresses) as TCP endpoints.
std::vector<asio::ip::tcp::endpoint> parse_endpoints(const std::string& text) {
  std::vector<asio::ip::tcp::endpoint> out;
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string item = text.substr(from, comma - from);
    const std::size_t colon = item.rfind(':');
    REQUIRE(colon != std::string::npos);
    out.emplace_back(asio::ip::make_address(item.substr(0, colon)),
                     static_cast<std::uint16_t>(std::stoi(item.substr(colon + 1))));
    from = comma + 1;
  }
  return out;
}

}  // namespace

TEST_CASE("replicas send byte-identical frames", "[replica]") {
  // The second replica starts 30 s after the first, with vessels: the wake lattice, which the first
  // stepped tick by tick and the second computed from its epochs' starts, must be byte-identical too.
  ReplicaPair pair(30.0, true);
  const Replicas replicas{pair.endpoints(), [&] { return pair.logs(); }, kEpochUnixMs};
  for (const char* name : {"mobile", "lite"}) {
    const Profile* profile = find_profile(name);
    REQUIRE(profile);
    check_profile(replicas, *profile);
  }
}

// Hidden (not run by CTest): replicas started elsewhere, e.g. the pods of deploy/k8s that
// deploy/container_test.sh starts with podman kube play. OCEAN_REPLICA_SERVERS lists them
// ("IP:PORT,IP:PORT,..."), OCEAN_REPLICA_PROFILES the profiles to compare (default "mobile").
// They must run at kTickRateHz.
TEST_CASE("replicas named in OCEAN_REPLICA_SERVERS send byte-identical frames", "[.][external]") {
  const char* servers = std::getenv("OCEAN_REPLICA_SERVERS");
  REQUIRE(servers);
  const Replicas replicas{parse_endpoints(servers), [] { return std::string("(external replicas: no logs here)"); }, std::nullopt,
                          true};
  REQUIRE(replicas.servers.size() >= 2);
  const char* profiles = std::getenv("OCEAN_REPLICA_PROFILES");
  std::stringstream names(profiles ? profiles : "mobile");
  for (std::string name; std::getline(names, name, ',');) {
    const Profile* profile = find_profile(name);
    INFO("profile " << name);
    REQUIRE(profile);
    check_profile(replicas, *profile);
  }
}
