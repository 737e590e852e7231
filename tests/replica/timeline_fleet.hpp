// The fleet-timeline test's rig (test_timeline_fleet.cpp): three replicas of one config following
// one etcd log, ocean-admin run beside the recordings, a relay that cuts one replica off from the
// store, and the checks that recordings of the replicas' streams agree byte for byte and in the
// sea their frames decode to.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
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

#include <asio/executor_work_guard.hpp>
#include <asio/post.hpp>
#include <asio/write.hpp>
#include <sys/wait.h>

#include "frame_recorder.hpp"
#include "profile.hpp"
#include "raw_http_get.hpp"
#include "replica_pair.hpp"
#include "run_until.hpp"
#include "server_process.hpp"
#include "stream_overlap.hpp"

namespace ocean::replica_test {

using test::run_until;

inline constexpr int kReplicas = 3;
// Under a sanitizer (OCEAN_SANITIZE) the replicas run several times slower: how fast a change
// travels, and how often a busy replica predicts from another baseline, are printed, not asserted.
#if defined(OCEAN_SANITIZED)
inline constexpr bool kTimingMeasurable = false;
#else
inline constexpr bool kTimingMeasurable = true;
#endif
// Deadlines for what must happen at all (a keyframe, an answer) are this many times longer there:
// each replica an ASan build several times slower, beside the test process and its recorders.
inline constexpr double kSlow = kTimingMeasurable ? 1.0 : 4.0;

// Three replicas of one config that follows the timeline at `timeline_url`.
class TimelineFleet {
 public:
  // `own_flags`: flags for one replica each (a --timeline through a relay), the rest the file's.
  // `lease_s`: each replica's lease on the store (--timeline-lease).
  explicit TimelineFleet(const std::string& timeline_url, std::vector<std::vector<std::string>> own_flags = {},
                         int lease_s = 10)
      : own_flags_(std::move(own_flags)) {
    std::ofstream(dir_.file("token")) << "fleet-admin-token\n";
    // Top-level keys before the config's [[vessel]] tables (after them they would be a vessel's).
    std::ofstream(dir_.file("ocean.toml")) << "timeline = \"" << timeline_url << "\"\n"
                                           << "timeline-lease = " << lease_s << "\n"
                                           << "admin-token-file = \"" << dir_.file("token") << "\"\n"
                                           << replica_config_toml(true, true);
    for (int i = 0; i < kReplicas; ++i) start_replica();
    for (auto& server : servers_) wait_listening(*server);
    started_ = std::chrono::steady_clock::now();
  }
  // Seconds since the replicas were listening.
  double age_s() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(); }
  // One more replica of the same config (a restarted or rescheduled pod); its index.
  int add_replica() {
    start_replica();
    wait_listening(*servers_.back());
    return static_cast<int>(servers_.size()) - 1;
  }
  asio::ip::tcp::endpoint endpoint(int i) const { return {asio::ip::address_v4::loopback(), servers_[i]->tcp_port()}; }
  std::string token_file() const { return dir_.file("token"); }
  // /readyz's status line and body, e.g. "503 timeline: stale, ...".
  std::string readyz(int i) const {
    const std::string reply = server::test::raw_http_get(servers_[i]->metrics_port(), "/readyz");
    const std::size_t body = reply.find("\r\n\r\n");
    return reply.substr(9, 3) + " " + (body == std::string::npos ? "" : reply.substr(body + 4));
  }
  double metric(int i, const std::string& name) const {
    const std::string reply = server::test::raw_http_get(servers_[i]->metrics_port(), "/metrics");
    const std::size_t at = reply.find("\n" + name + " ");
    return at == std::string::npos ? -1e9 : std::stod(reply.substr(at + name.size() + 2));
  }
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
    if (servers_.size() < own_flags_.size())
      options.args.insert(options.args.end(), own_flags_[servers_.size()].begin(), own_flags_[servers_.size()].end());
    options.log_path = dir_.file("replica-" + std::to_string(servers_.size()) + ".log");
    options.wait_listening = false;
    servers_.push_back(std::make_unique<ServerProcess>(std::move(options)));
  }
  void wait_listening(ServerProcess& server) const {
    const bool listening = server.wait_listening(30.0 * kSlow);
    INFO(logs());
    REQUIRE(listening);
  }

  std::vector<std::vector<std::string>> own_flags_;
  std::chrono::steady_clock::time_point started_;
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
inline std::vector<ProfileRecordings> record(asio::io_context& io, const std::vector<asio::ip::tcp::endpoint>& replicas,
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
    REQUIRE(run_until(io, [&] { return keyed([](const ProfileRecordings&, const FrameRecorder& r) { return r.first_key_tick().has_value(); }); }, 10.0 * kSlow));
    if (keyed([](const ProfileRecordings& p, const FrameRecorder& r) { return r.first_key_tick() == p.first().first_key_tick(); }))
      return all;
  }
  FAIL("no attempt keyed the three replicas' streams at one tick");
  return {};
}

// ocean-admin through replica A; true once every recording has had `n` SceneUpdates. Returns the
// milliseconds from ocean-admin's start to the last replica's announcement.
inline double change_through_a(asio::io_context& io, const TimelineFleet& fleet, const std::vector<ProfileRecordings>& all,
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
  }, 15.0 * kSlow));
  INFO("ocean-admin " << change);
  CHECK(admin.exit_code() == 0);
  return ms;
}

// A TCP relay to the store on a port of its own, on a thread of its own: a replica pointed at it
// can be cut off from the store (connections refused, open ones closed) while the others are not.
class StoreRelay {
 public:
  explicit StoreRelay(std::uint16_t store_port) : store_port_(store_port), acceptor_(io_) {
    open(0);
    thread_ = std::thread([this] {
      try {
        io_.run();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "StoreRelay: %s\n", e.what());
        throw;
      }
    });
  }
  ~StoreRelay() {
    work_.reset();
    asio::post(io_, [this] { close_all(); });
    io_.stop();
    thread_.join();
  }
  std::uint16_t port() const { return port_; }
  // Cut: open connections are closed, new ones closed as soon as they are accepted.
  void cut() {
    asio::post(io_, [this] {
      cut_ = true;
      close_pairs();
    });
  }
  void restore() { asio::post(io_, [this] { cut_ = false; }); }

 private:
  void open(std::uint16_t port) {
    acceptor_.open(asio::ip::tcp::v4());
    acceptor_.bind({asio::ip::address_v4::loopback(), port});
    acceptor_.listen();
    port_ = acceptor_.local_endpoint().port();
    accept();
  }
  void accept() {
    acceptor_.async_accept([this](std::error_code ec, asio::ip::tcp::socket client) {
      if (ec) return;
      if (cut_) {
        std::error_code ignored;
        client.close(ignored);
        return accept();
      }
      auto pair = std::make_shared<std::array<asio::ip::tcp::socket, 2>>(std::array{std::move(client), asio::ip::tcp::socket(io_)});
      std::error_code connect_error;
      (*pair)[1].connect({asio::ip::address_v4::loopback(), store_port_}, connect_error);
      if (!connect_error) {
        pairs_.push_back(pair);
        pipe(pair, 0, 1);
        pipe(pair, 1, 0);
      }
      accept();
    });
  }
  void pipe(const std::shared_ptr<std::array<asio::ip::tcp::socket, 2>>& pair, int from, int to) {
    auto buffer = std::make_shared<std::array<char, 16384>>();
    (*pair)[from].async_read_some(asio::buffer(*buffer), [this, pair, buffer, from, to](std::error_code ec, std::size_t n) {
      std::error_code ignored;
      if (ec || asio::write((*pair)[to], asio::buffer(*buffer, n), ignored) != n) {
        (*pair)[0].close(ignored);
        (*pair)[1].close(ignored);
        return;
      }
      pipe(pair, from, to);
    });
  }
  void close_all() {
    std::error_code ignored;
    acceptor_.close(ignored);
    close_pairs();
  }
  void close_pairs() {
    std::error_code ignored;
    for (auto& pair : pairs_) {
      (*pair)[0].close(ignored);
      (*pair)[1].close(ignored);
    }
    pairs_.clear();
  }

  std::uint16_t store_port_, port_ = 0;
  bool cut_ = false;
  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_ = asio::make_work_guard(io_);
  asio::ip::tcp::acceptor acceptor_;
  std::vector<std::shared_ptr<std::array<asio::ip::tcp::socket, 2>>> pairs_;
  std::thread thread_;
};

// The replicas' tick now, from the config's epoch and rate on this machine's clock.
inline Tick tick_now() {
  const auto unix_ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  return static_cast<Tick>((unix_ms - kEpochUnixMs) * kTickRateHz / 1000);
}

// Frames of a second and a half of a profile's stream, less a few.
inline std::size_t enough_frames(const Profile& profile) { return static_cast<std::size_t>(45 * profile.rate_hz / kTickRateHz) - 3; }

// Each replica's recording against the first: byte-identical wherever both reached a tick along
// the same baselines from the same keyframe. Returns, of the replicas, the most frames so compared
// from tick `from` on. (A busy replica may predict a delta from an older frame than the others,
// when its socket had not yet taken the newest: from there on the two streams are other chains
// and are not compared, as in test_replica.)
inline std::size_t check_same_bytes(const ProfileRecordings& p, Tick from, const char* from_what) {
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
inline std::size_t check_same_sea(const ProfileRecordings& p, Tick from, const char* from_what) {
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
inline void record_until(asio::io_context& io, std::vector<ProfileRecordings>& all, Tick until) {
  REQUIRE(run_until(io, [&] {
    return std::all_of(all.begin(), all.end(), [&](const ProfileRecordings& p) {
      return std::all_of(p.replicas.begin(), p.replicas.end(), [&](const auto& r) { return r->newest_tick() && *r->newest_tick() >= until; });
    });
  }, 10.0 * kSlow));
  for (auto& p : all)
    for (auto& r : p.replicas) r->close();
}

}  // namespace ocean::replica_test
