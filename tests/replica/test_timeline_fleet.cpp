// The fleet's timeline (issue 37) with real processes: one etcd and three ocean-server replicas of
// one config following its log (--timeline). Changes sent to replica A by ocean-admin are announced
// by all three for the same tick with the same serial; recordings of the three streams are
// byte-identical and decode to the same sea across them, and a fourth replica started 30 s after
// them streams that sea from its first frame. The store killed: the replicas go on and changes are
// refused; back: changes flow again. One replica cut off from the store: a change it cannot read is
// aborted while its lease lives; once the lease has lapsed it streams nothing until it has caught
// up, so its viewers never see a sea the log does not say. Figures are printed ("[timeline]" lines).
#include <catch2/catch.hpp>

#include <cmath>

#include "etcd_process.hpp"
#include "timeline_change.hpp"
#include "timeline_log.hpp"
#include "timeline_fleet.hpp"

using namespace ocean;
using namespace ocean::replica_test;
using test_support::EtcdProcess;

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
    if (kTimingMeasurable) CHECK(effective <= before + kTickRateHz + 6);  // and the change was taken within 200 ms
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
    CHECK(check_same_sea(p, first_change - kTickRateHz, "a second before the first change") + 3 >=
          (kTimingMeasurable ? span : span / 2));
  }
  // Byte for byte across the changes: a busy replica may predict its deltas from other baselines
  // (then that pair is not compared further), but on a machine that keeps up most pairs are
  // compared to the end, and one at least must be.
  if (kTimingMeasurable) CHECK(most_bytes_after_change >= 42);  // ticks: a second and a half, less a few

  // A replica started 30 s after the others, after every change, streams the log's sea from its
  // first frame: the same bytes as replica A, its first keyframe included.
  std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, 30.0 - fleet.age_s())));
  const int late = fleet.add_replica();
  for (const Profile* profile : profiles) {
    std::size_t bytes = 0, sea = 0;
    const auto enough = [&] { return sea >= enough_frames(*profile) && (bytes >= enough_frames(*profile) || !kTimingMeasurable); };
    for (int attempt = 0; attempt < 3 && !enough(); ++attempt) {
      std::vector<ProfileRecordings> joined = record(io, fleet.endpoints({0, late}), {profile});
      const Tick first_key = *joined.front().first().first_key_tick();
      record_until(io, joined, first_key + 45);
      const protocol::Welcome& mine = *joined.front().replicas[1]->welcome();
      const protocol::Welcome& first = *joined.front().first().welcome();
      CHECK(mine.scene == first.scene);
      CHECK(mine.scene_serial == first.scene_serial);
      CHECK(mine.stream == first.stream);
      CHECK(mine.vessels == first.vessels);
      bytes = check_same_bytes(joined.front(), first_key, "the late replica's first keyframe");
      sea = check_same_sea(joined.front(), first_key, "the late replica's first keyframe");
    }
    CHECK(enough());
  }

  std::vector<double> sorted = latencies_ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf("[timeline] %zu changes through replica A, ocean-admin's start to the last replica's announcement: median "
              "%.0f ms, max %.0f ms (scene change %.0f ms, vessel command %.0f ms)\n",
              sorted.size(), sorted[sorted.size() / 2], sorted.back(), latencies_ms[0], latencies_ms[1]);
  std::fflush(stdout);
  // Within the lead, or the change would have missed its tick somewhere (p99 on an idle machine:
  // the 200 ms, measured by this test's printout and quoted in the notes).
  if (kTimingMeasurable) CHECK(sorted.back() < 1000.0);
}

TEST_CASE("with the store killed the replicas go on and refuse changes with the reason, and when it is back a change "
          "reaches all of them again, nothing lost or applied twice",
          "[replica][timeline]") {
  EtcdProcess etcd;
  TimelineFleet fleet(etcd.url("/ocean/store-faults"));
  asio::io_context io;
  std::vector<ProfileRecordings> all = record(io, fleet.endpoints({0, 1, 2}), {find_profile("mobile")});
  ProfileRecordings& p = all.front();
  INFO(fleet.logs());
  const auto announced = [&](std::size_t n) {
    return std::all_of(p.replicas.begin(), p.replicas.end(), [&](const auto& r) { return r->scene_updates().size() == n; });
  };
  change_through_a(io, fleet, all, "--wind-speed 15", 1);

  etcd.stop();  // SIGKILL: the store is gone
  run_until(io, [] { return false; }, 1.5);
  const Tick outage_start = *p.first().newest_tick();
  for (int i = 0; i < kReplicas; ++i) {
    INFO("replica " << i);
    CHECK(fleet.readyz(i).rfind("503 timeline: stale", 0) == 0);
    CHECK(fleet.metric(i, "ocean_timeline_age_seconds") > 0.5);
  }
  {  // refused through B, with the store's error
    AdminRun refused(fleet.endpoint(1), fleet.token_file(), "--wind-speed 18");
    REQUIRE(run_until(io, [&] { return refused.done(); }, 15.0 * kSlow));
    CHECK(refused.exit_code() == 3);
    CHECK(fleet.metric(1, "ocean_timeline_refused_total") == 1.0);
  }
  run_until(io, [] { return false; }, 1.0);
  // The replicas went on streaming the timeline they hold.
  for (const auto& r : p.replicas) CHECK(*r->newest_tick() >= outage_start + (kTimingMeasurable ? kTickRateHz - 5 : 5));

  REQUIRE(etcd.start());  // back, with its data: the log as it was
  REQUIRE(run_until(io, [&] {
    for (int i = 0; i < kReplicas; ++i)
      if (fleet.readyz(i).rfind("200", 0) != 0) return false;
    return true;
  }, 10.0 * kSlow));
  change_through_a(io, fleet, all, "--wind-speed 12 --wind-dir 120", 2);
  const Tick last_change = p.first().scene_updates().back().effective_tick;
  record_until(io, all, last_change + 45);
  CHECK(announced(2));  // the refused change never appears, none twice
  CHECK(p.first().scene_updates()[1].scene.wind_dir_deg == 120.0);
  for (int i = 0; i < kReplicas; ++i) {
    CHECK(fleet.metric(i, "ocean_timeline_entries_total") == 2.0);
    CHECK(fleet.metric(i, "ocean_timeline_late_entries_total") == 0.0);
  }
  for (const auto& r : p.replicas) {
    REQUIRE(r->scene_updates().size() == 2);
    CHECK(r->scene_updates()[1] == p.first().scene_updates()[1]);
  }
  const Tick first_change = p.first().scene_updates().front().effective_tick;
  // Every tick from the first change to the last recorded (half of them under a sanitizer, whose
  // decoders fall behind), all alike.
  const Tick across = last_change + 40 - first_change;
  CHECK(check_same_sea(p, first_change, "the first change, across the outage") >= (kTimingMeasurable ? across : across / 2));

  // Entries written into the store by other hands: a damaged one, and a scene no profile can carry
  // (the appending replica would have refused it). Every replica skips both and goes on.
  std::string error;
  server::TimelineLog log(*server::parse_timeline_url(etcd.url("/ocean/store-faults"), error), 2.0);
  REQUIRE(log.append("not an entry").error.empty());
  server::TimelineChange storm;
  storm.update.effective_tick = tick_now() + kTickRateHz;
  storm.update.scene = p.first().scene_updates().back().scene;
  storm.update.scene.wind_speed_mps = 100.0;
  storm.update.scene.amplitude = 1e6;
  REQUIRE(log.append(server::encode_change(storm)).error.empty());
  REQUIRE(run_until(io, [&] {
    for (int i = 0; i < kReplicas; ++i)
      if (fleet.metric(i, "ocean_timeline_skipped_total") != 2.0) return false;
    return true;
  }, 5.0 * kSlow));
  for (int i = 0; i < kReplicas; ++i) {
    CHECK(fleet.metric(i, "ocean_timeline_entries_total") == 2.0);
    CHECK(fleet.readyz(i).rfind("200", 0) == 0);
  }

  std::printf("[timeline] store killed at tick %llu for about 3 s: the replicas streamed on, a change through B was "
              "refused (exit 3); after it came back a change reached all three at tick %llu\n",
              static_cast<unsigned long long>(outage_start), static_cast<unsigned long long>(last_change));
  std::fflush(stdout);
}

TEST_CASE("a replica cut off from the store never streams a sea the log does not say: a change it cannot read is "
          "aborted while its lease lives, and once its lease has lapsed it streams nothing until it has caught up",
          "[replica][timeline]") {
  EtcdProcess etcd;
  StoreRelay relay(etcd.client_port());
  const std::string prefix = "/ocean/partition";
  // etcd's shortest; under a sanitizer longer, so that the first change (0.3 s into the cut) is
  // surely decided while C's lease lives, however slowly the replicas take it.
  constexpr int kLeaseS = kTimingMeasurable ? 2 : 6;
  TimelineFleet fleet(etcd.url(prefix), {{}, {}, {"--timeline", "etcd://127.0.0.1:" + std::to_string(relay.port()) + prefix}},
                      kLeaseS);
  asio::io_context io;
  std::vector<ProfileRecordings> all = record(io, fleet.endpoints({0, 1, 2}), {find_profile("mobile")});
  ProfileRecordings& p = all.front();
  INFO(fleet.logs());
  std::string error;
  const server::TimelineLog log(*server::parse_timeline_url(etcd.url(prefix), error), 2.0);
  const auto members = [&] { return log.acks().read.size(); };
  REQUIRE(run_until(io, [&] { return members() == 3; }, 5.0 * kSlow));
  const double a_held_at_start = fleet.metric(0, "ocean_timeline_held_ticks_total");  // until it held its lease

  relay.cut();  // replica C alone loses the store
  const auto cut_at = std::chrono::steady_clock::now();
  run_until(io, [] { return false; }, 0.3);
  {  // Through A while C's lease lives: C cannot read it, so the fleet aborts it before its tick.
    AdminRun admin(fleet.endpoint(0), fleet.token_file(), "--wind-speed 18");
    REQUIRE(run_until(io, [&] { return admin.done(); }, 15.0 * kSlow));
    CHECK(admin.exit_code() == 3);
  }
  const double aborted_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - cut_at).count();
  for (const auto& r : p.replicas) CHECK(r->scene_updates().empty());
  CHECK(fleet.metric(0, "ocean_timeline_refused_total") == 1.0);

  // C's lease lapses: it says so and streams nothing; the store drops it from the members.
  REQUIRE(run_until(io, [&] { return fleet.readyz(2).rfind("503 timeline: this server's lease", 0) == 0; },
                    (kLeaseS + 2.0) * kSlow));
  REQUIRE(run_until(io, [&] { return members() == 2; }, (kLeaseS + 2.0) * kSlow));
  {  // Now through A: A and B take it; C, holding, cannot stream past it.
    AdminRun admin(fleet.endpoint(0), fleet.token_file(), "--wind-speed 17 --wind-dir 200");
    REQUIRE(run_until(io, [&] { return admin.done() && p.replicas[1]->scene_updates().size() == 1; }, 15.0 * kSlow));
    CHECK(admin.exit_code() == 0);
  }
  const Tick change = p.first().scene_updates().front().effective_tick;
  run_until(io, [&] { return *p.first().newest_tick() >= change + 15; }, 5.0 * kSlow);
  CHECK(p.replicas[2]->scene_updates().empty());
  const Tick c_last_held = *p.replicas[2]->newest_tick();
  CHECK(c_last_held < change);  // C streamed no frame from the change's tick on
  for (const auto& [replica, status] : {std::pair{0, 0}, std::pair{2, 3}}) {  // nor answers for its sea
    AdminRun query(fleet.endpoint(replica), fleet.token_file(), "query --at 0,0");
    REQUIRE(run_until(io, [&] { return query.done(); }, 10.0 * kSlow));
    INFO("ocean-admin query to replica " << replica);
    CHECK(query.exit_code() == status);
  }
  const double c_held = fleet.metric(2, "ocean_timeline_held_ticks_total");
  CHECK(c_held > 0.0);

  relay.restore();
  REQUIRE(run_until(io, [&] { return p.replicas[2]->scene_updates().size() == 1; }, (kLeaseS + 5.0) * kSlow));
  REQUIRE(run_until(io, [&] { return *p.replicas[2]->newest_tick() >= change; }, 5.0 * kSlow));
  const Tick resumed_at = *p.replicas[2]->newest_tick();
  record_until(io, all, resumed_at + 60);
  CHECK(fleet.metric(2, "ocean_timeline_late_entries_total") == 1.0);
  CHECK(fleet.metric(0, "ocean_timeline_late_entries_total") == 0.0);
  CHECK(fleet.metric(0, "ocean_timeline_held_ticks_total") == a_held_at_start);  // A and B never held
  CHECK(p.replicas[2]->scene_updates().front() == p.first().scene_updates().front());
  // Every frame C's viewer decoded, before the cut, while cut and after, is the log's sea: the
  // same heights as replica A's viewer (to the rounding of a decoder keyed at another tick than
  // A's: a micrometre, not bit for bit).
  float worst = 0.0f;
  std::size_t compared = 0, compared_after_change = 0;
  for (const auto& [tick, heights] : p.replicas[2]->heights()) {
    const auto a = p.first().heights().find(tick);
    if (a == p.first().heights().end() || a->second.size() != heights.size()) continue;
    for (std::size_t i = 0; i < heights.size(); ++i) worst = std::max(worst, std::abs(a->second[i] - heights[i]));
    ++compared;
    compared_after_change += tick >= change;
  }
  CHECK(worst < 1e-4f);
  CHECK(compared_after_change >= 30);
  std::printf("[timeline] replica C cut off from the store: a change through A %.1f s into the cut was aborted (exit 3); "
              "C's %d s lease lapsed, it streamed nothing after tick %llu (%.0f ticks held); a change through A then took effect at tick "
              "%llu on A and B; C caught up and streamed again from tick %llu: %zu ticks of C's viewer compared with A's "
              "(%zu from the change on), worst %.1e m\n",
              aborted_s, kLeaseS, static_cast<unsigned long long>(c_last_held), c_held, static_cast<unsigned long long>(change),
              static_cast<unsigned long long>(resumed_at), compared, compared_after_change, worst);
  std::fflush(stdout);
}

TEST_CASE("a server refuses a --timeline URL it cannot follow at once, and a store that never answers stops its start",
          "[replica][timeline]") {
  // Each bad form: exit 2 before listening, the option and the URL named.
  for (const char* bad : {"redis://127.0.0.1:6379/ocean", "etcd://127.0.0.1:2379", "etcd://127.0.0.1:0/ocean", "etcd://:2379/ocean"}) {
    test_support::ServerOptions options;
    options.args = {"--listen", "127.0.0.1:0", "--metrics-listen", "off", "--size", "64", "--profiles", "mobile", "--timeline", bad};
    options.wait_listening = false;
    ServerProcess server(options);
    const int status = server.wait_exit(20.0 * kSlow);
    INFO(bad << ": " << server.log());
    CHECK(status == 2);
    CHECK(server.log().find("--timeline") != std::string::npos);
    CHECK(server.log().find("listening") == std::string::npos);
  }
  // A well-formed URL whose store is not there: exit 1 within its 10 s, the store named; nothing served.
  test_support::ServerOptions options;
  options.args = {"--listen", "127.0.0.1:0", "--metrics-listen", "off", "--size", "64", "--profiles", "mobile",
                  "--timeline", "etcd://127.0.0.1:" + std::to_string(test_support::free_port()) + "/ocean/nowhere"};
  options.wait_listening = false;
  ServerProcess server(options);
  const int status = server.wait_exit(30.0 * kSlow);
  INFO(server.log());
  CHECK(status == 1);
  CHECK(server.log().find("did not answer within 10 s") != std::string::npos);
}
