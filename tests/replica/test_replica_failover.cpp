// Failover between replicas: a viewer's ClientConnection (UDP, mobile) is given both replicas.
// Replica A is SIGKILLed mid-stream; the viewer must reconnect to B within a few seconds, get
// exactly one keyframe there, and go on with deltas - every frame before and after within the
// profile's quantization bound of the simulation's own frame for its tick, ticks increasing.
#include <catch2/catch.hpp>

#include <chrono>
#include <optional>

#include "client_connection.hpp"
#include "frame_verdict.hpp"
#include "ground_truth.hpp"
#include "profile.hpp"
#include "replica_pair.hpp"
#include "run_until.hpp"

using namespace ocean;
using namespace ocean::replica_test;

namespace {

constexpr std::size_t kFramesBefore = 30;  // from A, once its deltas come by UDP
constexpr std::size_t kFramesAfter = 45;   // from B: 1.5 s of the 30 Hz stream
constexpr double kMaxFailoverS = 3.0;      // kill of A -> first frame shown from B

struct Shown {
  std::size_t server;         // ClientConnection::server_index() when shown
  std::uint64_t connect;      // connection number (counters().connects) it belongs to
  std::uint32_t tick;
  std::uint64_t keys;         // keyframes its session had completed by then
  double arrival_s;
  loadtest::FrameError error;
  bool within_bound;
};

using ocean::test::run_until;

}  // namespace

TEST_CASE("a viewer whose replica dies continues on another after one keyframe", "[replica][failover]") {
  ReplicaPair pair;
  const Profile& mobile = *find_profile("mobile");

  client::ClientConnectionConfig config;
  config.servers = {{"127.0.0.1", std::to_string(pair.port(0))}, {"127.0.0.1", std::to_string(pair.port(1))}};
  config.session.profile_id = mobile.id;
  config.session.transport = wire::Transport::udp;
  config.session.client_name = "replica-failover-test";
  // A loaded machine must not turn a slow UDP proof into a TCP fallback (and a second keyframe).
  config.session.udp_proof_timeout_s = 5.0;
  config.session.udp_silence_timeout_s = 5.0;
  config.reconnect_min_s = 0.1;

  asio::io_context io;
  std::optional<loadtest::GroundTruth> truth;
  loadtest::ErrorBounds bounds{0.0, 0.0};
  std::vector<protocol::Welcome> welcomes;
  std::vector<Shown> shown;
  std::shared_ptr<client::ClientConnection> connection;
  connection = client::ClientConnection::create(
      io, config, [&](const codec::ReconstructedFrame& frame, std::uint32_t tick, double arrival_s) {
        if (!truth) return;  // never: the Welcome comes first
        const sim::Frame& expected = *truth->at(tick, mobile.grid);
        const loadtest::FrameError error = loadtest::frame_error(frame.height, frame.slope_x, frame.slope_z,
                                                                 expected.height, expected.slope_x, expected.slope_z);
        shown.push_back({connection->server_index(), connection->counters().connects, tick,
                         connection->session()->stats().keyframes_complete, arrival_s, error,
                         loadtest::within_bounds(error, bounds)});
      });
  connection->set_on_welcome([&](const protocol::Welcome& w) {
    welcomes.push_back(w);
    if (!truth) {
      truth.emplace(static_cast<int>(std::lround(1.0 / w.tick_period_s)));
      truth->set_scene(0, w.scene);
      truth->set_wake(w.stream.wake, w.vessels, w.scene);  // the replicas run vessels
      bounds = {w.stream.height_step_m / 2.0, w.stream.normals ? w.stream.slope_step / 2.0 : 0.0};
    }
  });
  connection->start();
  INFO(pair.logs());

  // On A, streaming deltas by UDP.
  REQUIRE(run_until(io, [&] {
    return shown.size() >= kFramesBefore && connection->session()->path() == client::ClientSession::Path::udp;
  }, 15.0));
  CHECK(connection->server_index() == 0);
  const std::size_t from_a = shown.size();

  pair.server(0).kill();
  const double killed_at = client::ClientConnection::now_s();
  REQUIRE(run_until(io, [&] { return shown.size() >= from_a + kFramesAfter; }, 15.0));
  const client::ClientSession& session_b = *connection->session();
  const client::ConnectionCounters& counters = connection->counters();
  INFO("last close: " << counters.last_close_reason);

  // Reconnected to B, once, within a few seconds of the kill.
  CHECK(connection->server_index() == 1);
  CHECK(counters.connects == 2);
  CHECK(counters.disconnects == 1);
  CHECK(counters.failovers == 1);
  REQUIRE(welcomes.size() == 2);
  CHECK(welcomes[0].scene == welcomes[1].scene);
  CHECK(welcomes[0].stream == welcomes[1].stream);
  const Shown& first_b = shown[from_a];
  CHECK(first_b.server == 1);
  CHECK(first_b.arrival_s - killed_at < kMaxFailoverS);
  WARN("failover: first frame from replica B " << (first_b.arrival_s - killed_at) * 1000.0 << " ms after SIGKILL of A");

  // B's session: its first frame is its one keyframe, deltas follow (by UDP again), no other key.
  CHECK(first_b.keys == 1);
  CHECK(session_b.stats().keyframes_complete == 1);
  CHECK(session_b.stats().frames_complete >= kFramesAfter);
  CHECK(session_b.path() == client::ClientSession::Path::udp);
  CHECK(session_b.stats().udp.messages_in > 0);

  // Every frame, on either replica, within the bound of the sim's frame; ticks only go forward,
  // across the failover too (both replicas number ticks from one epoch).
  std::size_t out_of_bound = 0;
  double worst_height = 0.0;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const Shown& s = shown[i];
    INFO("frame " << i << " tick " << s.tick << " from replica " << s.server << ": height error " << s.error.height_m
                  << " m, slope error " << s.error.slope);
    if (!s.within_bound) ++out_of_bound;
    worst_height = std::max(worst_height, s.error.height_m);
    CHECK(s.server == (i < from_a ? 0u : 1u));
    CHECK(s.connect == (i < from_a ? 1u : 2u));
    CHECK(s.keys == 1);  // each session shows its keyframe first and receives no other
    if (i > 0) CHECK(s.tick > shown[i - 1].tick);
  }
  CHECK(out_of_bound == 0);
  CHECK(worst_height <= bounds.height_m + loadtest::kTruthSlack);
  WARN("frames: " << from_a << " from A, " << shown.size() - from_a << " from B; worst height error " << worst_height
                  << " m (bound " << bounds.height_m << " m)");

  connection->stop();
  io.run_for(std::chrono::milliseconds(50));
}
