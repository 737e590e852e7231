// The fleet's timeline (issue 37) with real processes: one etcd and three ocean-server replicas of
// one config following its log (--timeline). A scene change and a vessel command sent to replica A
// by ocean-admin are announced by all three for the same tick with the same serial, and raw TCP
// recordings of the three streams, from one keyframe tick across both changes, are byte-identical
// frame for frame; a fourth replica started after the changes streams the same bytes from its first
// keyframe. The time from ocean-admin's start to the last replica's announcement is printed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "etcd_process.hpp"
#include "frame_recorder.hpp"
#include "profile.hpp"
#include "replica_pair.hpp"
#include "run_until.hpp"
#include "stream_overlap.hpp"

using namespace ocean;
using namespace ocean::replica_test;
using ocean::test::run_until;
using test_support::EtcdProcess;

namespace {

constexpr int kReplicas = 3;
constexpr std::uint8_t kMobile = 1;

// Three replicas of one config that follows the timeline at `timeline_url`.
class TimelineFleet {
 public:
  TimelineFleet(const std::string& timeline_url) {
    std::ofstream(dir_.file("token")) << "fleet-admin-token\n";
    // Top-level keys before the config's [[vessel]] tables (after them they would be a vessel's).
    std::ofstream(dir_.file("ocean.toml")) << "timeline = \"" << timeline_url << "\"\n"
                                           << "admin-token-file = \"" << dir_.file("token") << "\"\n"
                                           << replica_config_toml(true);
    for (int i = 0; i < kReplicas; ++i) start_replica();
    for (auto& server : servers_) wait_listening(*server);
  }
  // One more replica of the same config (a restarted or rescheduled pod); its index.
  int add_replica() {
    start_replica();
    wait_listening(*servers_.back());
    return static_cast<int>(servers_.size()) - 1;
  }
  asio::ip::tcp::endpoint endpoint(int i) const { return {asio::ip::address_v4::loopback(), servers_[i]->tcp_port()}; }
  std::string token_file() const { return dir_.file("token"); }
  std::vector<asio::ip::tcp::endpoint> endpoints(std::initializer_list<int> which) const {
    std::vector<asio::ip::tcp::endpoint> out;
    for (int i : which) out.push_back(endpoint(i));
    return out;
  }
  std::string logs() const {
    std::string all;
    for (std::size_t i = 0; i < servers_.size(); ++i) all += "replica " + std::to_string(i) + ":\n" + servers_[i]->log();
    return all;
  }

 private:
  void start_replica() {
    test_support::ServerOptions options;
    options.args = {"--config", dir_.file("ocean.toml")};
    options.log_path = dir_.file("replica-" + std::to_string(servers_.size()) + ".log");
    options.wait_listening = false;
    servers_.push_back(std::make_unique<ServerProcess>(std::move(options)));
  }
  void wait_listening(ServerProcess& server) const {
    const bool listening = server.wait_listening(30.0);
    INFO(logs());
    REQUIRE(listening);
  }

  TempDir dir_;
  std::vector<std::unique_ptr<ServerProcess>> servers_;
};

// ocean-admin against one replica, on a thread of its own (the recordings go on meanwhile).
class AdminRun {
 public:
  AdminRun(const asio::ip::tcp::endpoint& server, const std::string& token_file, const std::string& args) {
    const std::string command = test_support::build_binary("tools/admin/ocean-admin") + " --server 127.0.0.1:" +
                                std::to_string(server.port()) + " --token-file " + token_file + " " + args + " >/dev/null";
    started_ = std::chrono::steady_clock::now();
    thread_ = std::thread([this, command] {
      status_ = std::system(command.c_str());
      done_ = true;
    });
  }
  ~AdminRun() { thread_.join(); }
  bool done() const { return done_; }
  int exit_code() const { return WIFEXITED(status_.load()) ? WEXITSTATUS(status_.load()) : -1; }
  std::chrono::steady_clock::time_point started() const { return started_; }

 private:
  std::chrono::steady_clock::time_point started_;
  std::atomic<int> status_{-1};
  std::atomic<bool> done_{false};
  std::thread thread_;
};

// One profile's stream from every replica, recorded from one keyframe tick.
struct ProfileRecordings {
  const Profile* profile;
  std::vector<std::unique_ptr<FrameRecorder>> replicas;
  const FrameRecorder& first() const { return *replicas.front(); }
};

// Records each profile from every replica, each profile's three streams keyed at one tick (a
// Hello that straddles a key tick starts another: then again).
std::vector<ProfileRecordings> record(asio::io_context& io, const std::vector<asio::ip::tcp::endpoint>& replicas,
                                      const std::vector<const Profile*>& profiles) {
  for (int attempt = 0; attempt < 4; ++attempt) {
    std::vector<ProfileRecordings> all;
    for (const Profile* profile : profiles) {
      all.push_back({profile, {}});
      for (const auto& replica : replicas) all.back().replicas.push_back(std::make_unique<FrameRecorder>(io, replica, profile->id));
    }
    sleep_to_frame_phase(2, 0.25);  // mid-tick for a 30 Hz and a 15 Hz profile alike
    for (auto& p : all)
      for (auto& r : p.replicas) r->send_hello();
    const auto keyed = [&](auto&& same) {
      return std::all_of(all.begin(), all.end(), [&](const ProfileRecordings& p) {
        return std::all_of(p.replicas.begin(), p.replicas.end(), [&](const auto& r) { return same(p, *r); });
      });
    };
    REQUIRE(run_until(io, [&] { return keyed([](const ProfileRecordings&, const FrameRecorder& r) { return r.first_key_tick().has_value(); }); }, 10.0));
    if (keyed([](const ProfileRecordings& p, const FrameRecorder& r) { return r.first_key_tick() == p.first().first_key_tick(); }))
      return all;
  }
  FAIL("no attempt keyed the three replicas' streams at one tick");
  return {};
}

// ocean-admin through replica A; true once every recording has had `n` SceneUpdates. Returns the
// milliseconds from ocean-admin's start to the last replica's announcement.
double change_through_a(asio::io_context& io, const TimelineFleet& fleet, const std::vector<ProfileRecordings>& all,
                        const std::string& change, std::size_t n) {
  AdminRun admin(fleet.endpoint(0), fleet.token_file(), change);
  const auto announced = [&] {
    return std::all_of(all.begin(), all.end(), [&](const ProfileRecordings& p) {
      return std::all_of(p.replicas.begin(), p.replicas.end(), [&](const auto& r) { return r->scene_updates().size() >= n; });
    });
  };
  double ms = -1.0;
  REQUIRE(run_until(io, [&] {
    if (announced() && ms < 0.0) ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - admin.started()).count();
    return admin.done() && ms >= 0.0;
  }, 15.0));
  INFO("ocean-admin " << change);
  CHECK(admin.exit_code() == 0);
  return ms;
}

// The replicas' tick now, from the config's epoch and rate on this machine's clock.
Tick tick_now() {
  const auto unix_ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  return static_cast<Tick>((unix_ms - kEpochUnixMs) * kTickRateHz / 1000);
}

// Frames of a second and a half of a profile's stream, less a few.
std::size_t enough_frames(const Profile& profile) { return static_cast<std::size_t>(45 * profile.rate_hz / kTickRateHz) - 3; }

// Each replica's recording against the first: byte-identical wherever both reached a tick along
// the same baselines from the same keyframe. Returns, of the replicas, the most frames so compared
// from tick `from` on. (A busy replica may predict a delta from an older frame than the others,
// when its socket had not yet taken the newest: from there on the two streams are other chains
// and are not compared, as in test_replica.)
std::size_t check_same_bytes(const ProfileRecordings& p, Tick from, const char* from_what) {
  const FrameRecorder& a = p.first();
  INFO("profile " << p.profile->name);
  std::size_t most = 0;
  for (std::size_t i = 1; i < p.replicas.size(); ++i) {
    const Overlap o = compare(a, *p.replicas[i]);
    std::string mismatches;
    for (const std::string& m : o.mismatches) mismatches += m + "; ";
    INFO("replica 0: " << describe(a) << "; replica " << i << ": " << describe(*p.replicas[i]) << "; mismatches: " << mismatches);
    CHECK(o.mismatched_chunks == 0);
    CHECK(o.keys >= 1);
    std::size_t after = 0;
    for (const auto& [tick, frame] : a.frames())
      if (tick >= from && !lineage(a, tick).empty() && lineage(a, tick) == lineage(*p.replicas[i], tick)) ++after;
    most = std::max(most, after);
    std::printf("[timeline] %.*s, replica %zu against replica 0: %zu key(s) + %zu deltas compared (%zu chunks, %zu "
                "bytes; %zu from %s), %zu chunks differ, %zu frames reached by other baselines\n",
                static_cast<int>(p.profile->name.size()), p.profile->name.data(), i, o.keys, o.deltas, o.chunks, o.bytes,
                after, from_what, o.mismatched_chunks, o.other_lineage);
  }
  return most;
}

// Each replica's decoded sea (the recorder's listening ClientSession) against the first's, tick by
// tick: a frame's bytes may carry no wave at all - the client predicts the sea from the scenes and
// fleets announced - so the sea itself is compared: a scene from another tick, or a late replica
// that missed a change, shows in the heights, not in the bytes. The recordings began at one
// keyframe tick (a decoder's rounding follows its path from its keyframe). Returns the fewest
// ticks compared from `from` on; every one must be alike.
std::size_t check_same_sea(const ProfileRecordings& p, Tick from, const char* from_what) {
  std::size_t least = std::numeric_limits<std::size_t>::max();
  for (std::size_t i = 1; i < p.replicas.size(); ++i) {
    std::size_t same = 0, differ = 0;
    std::optional<Tick> first_differ;
    for (const auto& [tick, hash] : p.first().sea()) {
      const auto other = p.replicas[i]->sea().find(tick);
      if (tick < from || other == p.replicas[i]->sea().end()) continue;
      if (other->second == hash) ++same;
      else if (differ++ == 0) first_differ = tick;
    }
    INFO("profile " << p.profile->name << ", replica " << i << " against replica 0: " << same << " ticks alike from "
                    << from_what << ", " << differ << " differ (the first at tick " << first_differ.value_or(0) << ")");
    CHECK(differ == 0);
    least = std::min(least, same);
    std::printf("[timeline] %.*s, replica %zu against replica 0: the decoded sea alike at %zu ticks from %s, %zu differ\n",
                static_cast<int>(p.profile->name.size()), p.profile->name.data(), i, same, from_what, differ);
  }
  return least == std::numeric_limits<std::size_t>::max() ? 0 : least;
}

// Runs the recordings until every stream has reached tick `until`.
void record_until(asio::io_context& io, std::vector<ProfileRecordings>& all, Tick until) {
  REQUIRE(run_until(io, [&] {
    return std::all_of(all.begin(), all.end(), [&](const ProfileRecordings& p) {
      return std::all_of(p.replicas.begin(), p.replicas.end(), [&](const auto& r) { return r->newest_tick() && *r->newest_tick() >= until; });
    });
  }, 10.0));
  for (auto& p : all)
    for (auto& r : p.replicas) r->close();
}

}  // namespace

TEST_CASE("a scene change and a vessel command sent to one replica reach all three at the same tick, their streams "
          "stay byte-identical, and a replica started later streams the same bytes from its first frame",
          "[replica][timeline]") {
  EtcdProcess etcd;
  TimelineFleet fleet(etcd.url("/ocean/fleet-test"));
  asio::io_context io;
  const std::vector<const Profile*> profiles = {find_profile("mobile"), find_profile("lite")};
  std::vector<ProfileRecordings> all = record(io, fleet.endpoints({0, 1, 2}), profiles);
  INFO(fleet.logs());
  // A change of the weather, a vessel's course, then more weather as fast as the admin rate lets
  // them through: each announced by all three within the lead.
  const std::vector<std::string> changes = {"--wind-speed 16 --wind-dir 60", "--vessel course --id 1 --heading 90 --speed 6",
                                            "--wind-speed 13", "--wind-speed 14", "--wind-speed 15", "--wind-speed 12",
                                            "--wind-speed 11", "--wind-speed 10"};
  std::vector<double> latencies_ms;
  for (std::size_t c = 0; c < changes.size(); ++c) {
    if (c >= 3) run_until(io, [] { return false; }, 1.0);  // a server takes 4 changes at once, then 1 a second
    const Tick before = tick_now();
    latencies_ms.push_back(change_through_a(io, fleet, all, changes[c], c + 1));
    const Tick effective = all.front().first().scene_updates().back().effective_tick;
    INFO("ocean-admin " << changes[c] << " started at tick " << before << ", effective from tick " << effective);
    CHECK(effective >= before + kTickRateHz - 1);  // the lead stays a second (the admin's tick may be one old)
    CHECK(effective <= before + kTickRateHz + 6);  // and the change was taken within 200 ms
  }
  const Tick last_change = all.front().first().scene_updates().back().effective_tick;
  record_until(io, all, last_change + 45);  // a second and a half past the last change

  std::size_t most_bytes_after_change = 0;  // ticks, over every profile's pairs
  for (const ProfileRecordings& p : all) {
    const FrameRecorder& a = p.first();
    INFO("profile " << p.profile->name);
    // Every replica announced the same scenes, fleets and serials for the same ticks.
    for (const auto& r : p.replicas) {
      CHECK(r->faults().empty());
      REQUIRE(r->scene_updates().size() == changes.size());
      for (std::size_t i = 0; i < changes.size(); ++i) {
        CHECK(r->scene_updates()[i].effective_tick == a.scene_updates()[i].effective_tick);
        CHECK(r->scene_updates()[i].serial == a.scene_updates()[i].serial);
        CHECK(r->scene_updates()[i].scene == a.scene_updates()[i].scene);
        CHECK(r->scene_updates()[i].vessels == a.scene_updates()[i].vessels);
      }
    }
    CHECK(a.scene_updates()[0].scene.wind_speed_mps == 16.0);
    CHECK(a.scene_updates()[1].vessels.has_value());
    const std::size_t bytes_after = check_same_bytes(p, last_change, "the last change's tick");
    most_bytes_after_change = std::max(most_bytes_after_change, bytes_after * kTickRateHz / p.profile->rate_hz);
    // The sea across every change, from a second before the first.
    const Tick first_change = a.scene_updates().front().effective_tick;
    const std::size_t span = (last_change + 45 - (first_change - kTickRateHz)) * p.profile->rate_hz / kTickRateHz;
    CHECK(check_same_sea(p, first_change - kTickRateHz, "a second before the first change") + 3 >= span);
  }
  // Byte for byte across the changes: a busy replica may predict its deltas from other baselines
  // (then that pair is not compared further), but on a machine that keeps up most pairs are
  // compared to the end, and one at least must be.
  CHECK(most_bytes_after_change >= 42);  // ticks: a second and a half, less a few

  // A replica started after every change streams the log's sea from its first frame: the same
  // bytes as replica A, its first keyframe included.
  const int late = fleet.add_replica();
  for (const Profile* profile : profiles) {
    std::size_t compared = 0;
    for (int attempt = 0; attempt < 3 && compared < enough_frames(*profile); ++attempt) {
      std::vector<ProfileRecordings> joined = record(io, fleet.endpoints({0, late}), {profile});
      const Tick first_key = *joined.front().first().first_key_tick();
      record_until(io, joined, first_key + 45);
      const protocol::Welcome& mine = *joined.front().replicas[1]->welcome();
      const protocol::Welcome& first = *joined.front().first().welcome();
      CHECK(mine.scene == first.scene);
      CHECK(mine.scene_serial == first.scene_serial);
      CHECK(mine.stream == first.stream);
      CHECK(mine.vessels == first.vessels);
      compared = std::min(check_same_bytes(joined.front(), first_key, "the late replica's first keyframe"),
                          check_same_sea(joined.front(), first_key, "the late replica's first keyframe"));
    }
    CHECK(compared >= enough_frames(*profile));
  }

  std::vector<double> sorted = latencies_ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf("[timeline] %zu changes through replica A, ocean-admin's start to the last replica's announcement: median "
              "%.0f ms, max %.0f ms (scene change %.0f ms, vessel command %.0f ms)\n",
              sorted.size(), sorted[sorted.size() / 2], sorted.back(), latencies_ms[0], latencies_ms[1]);
  std::fflush(stdout);
  // Within the lead, or the change would have missed its tick somewhere (p99 on an idle machine:
  // the 200 ms, measured by this test's printout and quoted in the notes).
  CHECK(sorted.back() < 1000.0);
}
