// HeightQuery: the sea a game server asks for at a batch of points, against what a viewer of the
// same stream decoded there (codec::SurfaceQuery over its own frame of the answer's tick): the two
// differ only by the stream's bound, calm and choppy, over the sea's tile and a vessel's wake. And
// the abuse an admin interface meets: no token, too many points, non-finite points, a flood.
#include "session_harness.hpp"
#include "surface_query.hpp"

#include <cmath>
#include <iterator>
#include <limits>
#include <thread>

using namespace ocean::server;
using namespace ocean::server::test;
namespace proto = ocean::protocol;

namespace {

constexpr const char* kToken = "s3cret-token";

ServerConfig wake_config() {
  ServerConfig config = session_test_config();
  config.admin_token = kToken;
  config.profiles = {"mobile", "mobile-choppy"};
  config.scene.choppiness = 1.0;
  config.scene.wind_speed_mps = 9.0;
  // One vessel to and fro at 7 m/s across the queried points whatever the clock, so the answers
  // sample its wake too.
  ocean::model::VesselTrack vessel;
  vessel.id = 1;
  vessel.hull = {30.0, 7.0, 2.0};
  vessel.repeat = true;
  vessel.points = {{0.0, -100.0, 0.0}, {30.0, 110.0, 0.0}, {60.0, -100.0, 0.0}};
  config.vessels = {vessel};
  return config;
}

proto::HeightQuery query_of(std::uint8_t profile, std::uint32_t request_id) {
  proto::HeightQuery q{kToken, request_id, profile, {}};
  // 20 x 20 points over 150 m x 60 m around the vessel's track: its tile repeats, its wake does not.
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) q.points.emplace_back(-40.0 + 7.5 * i + 0.37 * j, -30.0 + 3.0 * j + 0.11 * i);
  return q;
}

}  // namespace

TEST_CASE("a HeightQuery's answer is the viewer's height_at within the stream's bound, calm and choppy") {
  SessionHarness harness(wake_config());
  for (const std::uint8_t profile : {std::uint8_t{1}, std::uint8_t{5}}) {
    auto viewer = harness.client();
    viewer->keep_frames = true;
    viewer->hello(proto::Hello{profile, 0, ocean::wire::Transport::tcp, "viewer"});
    // A few frames in (a sanitizer build decodes a choppy stream with a wake at a few a second).
    const bool started = pump_until({viewer.get()}, [&] { return viewer->completed_heights.size() > 3; }, std::chrono::seconds(60));
    INFO("profile " << int(profile) << ": " << viewer->progress());
    REQUIRE(started);
    REQUIRE(viewer->stream_config().has_wake());
    const proto::HeightQuery query = query_of(profile, 40 + profile);
    viewer->send_tcp(proto::encode(query));
    REQUIRE(pump_until({viewer.get()}, [&] { return !viewer->height_answers.empty() || !viewer->errors.empty(); },
                       std::chrono::seconds(60)));
    REQUIRE(viewer->errors.empty());
    const proto::HeightAnswer answer = viewer->height_answers.front();
    CHECK(answer.request_id == query.request_id);
    CHECK(answer.profile_id == profile);
    REQUIRE(answer.samples.size() == query.points.size());
    REQUIRE(pump_until({viewer.get()}, [&] { return viewer->completed_frames.count(answer.tick) > 0; },
                       std::chrono::seconds(60)));

    const ocean::codec::StreamConfig& config = viewer->stream_config();
    const ocean::codec::SurfaceQuery sea(config);
    const ocean::codec::ReconstructedFrame& frame = viewer->completed_frames.at(answer.tick);
    double worst_height = 0.0, worst_normal = 0.0, moving = 0.0, wake_seen = 0.0;
    std::size_t in_wake = 0;
    for (std::size_t i = 0; i < query.points.size(); ++i) {
      const double x = query.points[i].x_m(), z = query.points[i].z_m();
      const ocean::codec::SurfaceQuery::Point seen = sea.at(frame, x, z);
      const ocean::wire::SurfaceSample& truth = answer.samples[i];
      worst_height = std::max(worst_height, std::abs(seen.height_m - truth.height_m()));
      worst_normal = std::max({worst_normal, std::abs(seen.normal[0] - truth.normal_x()), std::abs(seen.normal[2] - truth.normal_z())});
      moving = std::max(moving, static_cast<double>(std::abs(truth.vertical_velocity_mps())));
      const double u = (x - config.wake.origin_x_m) / config.wake.size_m, v = (z - config.wake.origin_z_m) / config.wake.size_m;
      in_wake += u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0;
      wake_seen = std::max(wake_seen, std::abs(seen.height_m - sea.height_at(frame, x, z, ocean::codec::SurfaceQuery::Lattices::sea)));
    }
    INFO("profile " << int(profile) << ": worst height difference " << worst_height << " m, normal " << worst_normal);
    CHECK(in_wake == query.points.size());
    CHECK(wake_seen > 0.05);  // the hull's wake (its depression alone is metres deep) is among the points
    // Each sample the viewer holds is within step / 2 of the server's (CODEC.md 6), and a bilinear
    // blend of samples stays within it; the tile's and the wake's lattices each add their own.
    CHECK(worst_height <= config.height_step_m);
    CHECK(worst_height > 0.0);  // the viewer's sea is the quantized one, not the server's
    // Normals from slopes within slope_step / 2 each: a unit normal moves by less than that.
    CHECK(worst_normal <= config.slope_step);
    CHECK(moving > 0.05);  // a sea at 9 m/s: some water rises or falls faster than 5 cm/s
    viewer->send_tcp(proto::encode(proto::Bye{ocean::wire::ByeReason::client_quit, "done"}));
  }
}

TEST_CASE("the points budget of every connection together holds two admins to it, with the wait") {
  SessionCoreOptions options;
  // A 400-point batch leaves 100 of the burst, and 400 more are a minute of refill away: more than
  // any build on a busy machine takes between the two admins' batches (at 100 points a second, 3 s
  // of refill, a TSan build under CI's load once answered both). 110 points are 2 s away.
  options.query_points_per_s = 5.0;
  options.query_point_burst = 500.0;
  SessionHarness harness(wake_config(), options);
  auto first = harness.client(), second = harness.client();
  first->hello(proto::Hello{1, 0, ocean::wire::Transport::tcp, "admin-1"});
  second->hello(proto::Hello{1, 0, ocean::wire::Transport::tcp, "admin-2"});
  const std::vector<SessionTestClient*> all{first.get(), second.get()};
  const bool started = pump_until(
      all, [&] { return first->completed_heights.size() > 3 && second->completed_heights.size() > 3; }, std::chrono::seconds(60));
  INFO("first: " << first->progress() << "; second: " << second->progress());
  REQUIRE(started);
  first->send_tcp(proto::encode(query_of(1, 1)));
  REQUIRE(pump_until(all, [&] { return first->height_answers.size() == 1; }));
  second->send_tcp(proto::encode(query_of(1, 2)));  // 400 more points within the same minute
  REQUIRE(pump_until(all, [&] { return !second->errors.empty() || !second->height_answers.empty(); }));
  REQUIRE(second->errors.size() == 1);
  CHECK(second->errors[0].code == proto::Reason::rate_limited);
  CHECK(second->errors[0].text.find("query points a second over every connection") != std::string::npos);
  CHECK(second->errors[0].text.find("retry in") != std::string::npos);
  // 110 points: more than the 100 left, so answered only once the budget has refilled (2 s).
  proto::HeightQuery small = query_of(1, 3);
  small.points.resize(110);
  std::this_thread::sleep_for(std::chrono::milliseconds(3100));
  second->send_tcp(proto::encode(small));
  REQUIRE(pump_until(all, [&] { return !second->height_answers.empty() || second->errors.size() > 1; }));
  CHECK(second->errors.size() == 1);
  CHECK(!second->height_answers.empty());
  CHECK(!second->closed());
}

TEST_CASE("HeightQuery abuse is refused with reasons while viewers keep streaming") {
  SessionHarness harness(wake_config());
  auto viewer = harness.client();
  viewer->hello(proto::Hello{1, 0, ocean::wire::Transport::udp, "viewer"});
  auto admin = harness.client();
  admin->hello(proto::Hello{1, 0, ocean::wire::Transport::tcp, "admin"});
  const std::vector<SessionTestClient*> all{viewer.get(), admin.get()};
  // A sanitizer build decodes two streams with a wake at a few frames a second.
  const bool started = pump_until(
      all, [&] { return viewer->completed_heights.size() > 3 && admin->completed_heights.size() > 3; }, std::chrono::seconds(60));
  INFO("viewer: " << viewer->progress() << "; admin: " << admin->progress());
  REQUIRE(started);

  SECTION("a wrong token, an unoffered or unknown profile, no token: each refused by name") {
    proto::HeightQuery q = query_of(1, 1);
    q.admin_token = "wrong";
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->errors.size() == 1; }));
    CHECK(admin->errors[0].code == proto::Reason::unauthorized);
    CHECK(admin->errors[0].text.find("HeightQuery.admin_token") != std::string::npos);
    q.admin_token = kToken;
    q.profile_id = 4;  // lite: a profile, not offered here
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->errors.size() == 2; }));
    CHECK(admin->errors[1].code == proto::Reason::profile_unavailable);
    q.profile_id = 99;
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->errors.size() == 3; }));
    CHECK(admin->errors[2].code == proto::Reason::unknown_profile);
    CHECK(admin->height_answers.empty());
    q.admin_token.clear();  // no token at all: the message is malformed
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->errors.size() == 4; }));
    CHECK(admin->errors[3].code == proto::Reason::missing_field);
    CHECK(admin->errors[3].text.find("HeightQuery.admin_token") != std::string::npos);
  }
  SECTION("oversized and non-finite batches are refused by name") {
    proto::HeightQuery q = query_of(1, 2);
    q.points.resize(proto::kMaxQueryPoints + 1, q.points.front());
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return !admin->errors.empty(); }));
    CHECK(admin->errors[0].code == proto::Reason::oversized);
    CHECK(admin->errors[0].text.find("HeightQuery.points") != std::string::npos);
    auto other = harness.client();
    other->hello(proto::Hello{1, 0, ocean::wire::Transport::tcp, "admin-2"});
    q = query_of(1, 3);
    q.points[7] = ocean::wire::QueryPoint(std::nan(""), 1.0);
    other->send_tcp(proto::encode(q));
    REQUIRE(pump_until({other.get(), viewer.get()}, [&] { return !other->errors.empty(); }));
    CHECK(other->errors[0].code == proto::Reason::non_finite_value);
  }
  SECTION("a proven admin is answered at its rate; a flood is refused, then closed") {
    proto::HeightQuery q = query_of(0, 10);
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->height_answers.size() == 1; }));
    CHECK(admin->height_answers[0].profile_id == 1);  // 0: the first offered profile
    admin->height_answers.clear();
    // As fast as the answers come, never waiting for the retry: the burst is answered, then each
    // is refused with its wait, and a connection that ignores the waits is closed.
    const auto answered = [&] { return admin->height_answers.size() + admin->errors.size(); };
    const auto flood_start = std::chrono::steady_clock::now();
    for (std::uint32_t i = 0; i < 200 && !admin->closed(); ++i) {
      q.request_id = 100 + i;
      const std::size_t seen = answered();
      admin->send_tcp(proto::encode(q));
      REQUIRE(pump_until(all, [&] { return answered() > seen || admin->closed(); }));
    }
    INFO("answers " << admin->height_answers.size() << " errors " << admin->errors.size() << " in "
                    << std::chrono::duration<double>(std::chrono::steady_clock::now() - flood_start).count() << " s");
    REQUIRE(pump_until(all, [&] { return admin->closed(); }));
    CHECK(admin->height_answers.size() >= 20);  // the burst
    CHECK(admin->height_answers.size() < 100);
    REQUIRE(!admin->errors.empty());
    CHECK(admin->errors.front().code == proto::Reason::rate_limited);
    CHECK(admin->errors.front().text.find("retry in") != std::string::npos);
    CHECK(admin->errors.back().text.find("closing") != std::string::npos);
  }
  SECTION("the corners of a batch: 1 point, 2048 points anywhere in the doubles, every profile id") {
    proto::HeightQuery q = query_of(0, 20);
    q.points = {ocean::wire::QueryPoint(0.0, 0.0)};
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->height_answers.size() == 1; }));
    CHECK(admin->height_answers[0].samples.size() == 1);
    // The full batch, from the largest doubles to the wake square's edges and one ulp past them.
    const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
    const double edges[] = {-big, -1e300, -1e15, -256.0, std::nextafter(-256.0, -300.0), -tiny, 0.0, tiny,
                            std::nextafter(256.0, 0.0), 256.0, 1e15, 1e300, big};
    q.points.clear();
    for (std::size_t i = 0; q.points.size() < proto::kMaxQueryPoints; ++i)
      q.points.emplace_back(edges[i % std::size(edges)], edges[(i / std::size(edges)) % std::size(edges)]);
    q.request_id = 21;
    admin->send_tcp(proto::encode(q));
    REQUIRE(pump_until(all, [&] { return admin->height_answers.size() == 2; }));
    REQUIRE(admin->height_answers[1].samples.size() == proto::kMaxQueryPoints);
    for (const ocean::wire::SurfaceSample& sample : admin->height_answers[1].samples) {
      CHECK(std::isfinite(sample.height_m()));
      CHECK(std::abs(sample.height_m()) < 50.0f);  // a 9 m/s sea and one hull's wake
      CHECK(std::isfinite(sample.vertical_velocity_mps()));
      CHECK(sample.normal_y() > 0.0f);
    }
    for (const int profile : {5, 2, 255}) {  // offered; a profile not offered; no profile at all
      q.profile_id = static_cast<std::uint8_t>(profile);
      q.request_id = 30 + profile;
      const std::size_t seen = admin->errors.size() + admin->height_answers.size();
      admin->send_tcp(proto::encode(q));
      REQUIRE(pump_until(all, [&] { return admin->errors.size() + admin->height_answers.size() > seen; }));
    }
    REQUIRE(admin->height_answers.size() == 3);
    CHECK(admin->height_answers[2].profile_id == 5);
    REQUIRE(admin->errors.size() == 2);
    CHECK(admin->errors[0].code == proto::Reason::profile_unavailable);
    CHECK(admin->errors[1].code == proto::Reason::unknown_profile);
  }
  SECTION("a flood that reads nothing is closed") {
    proto::HeightQuery q = query_of(0, 10);
    for (std::uint32_t i = 0; i < 400 && !admin->closed(); ++i) {
      q.request_id = 100 + i;
      admin->send_tcp(proto::encode(q));
    }
    REQUIRE(pump_until(all, [&] { return admin->closed(); }));
    CHECK(admin->height_answers.size() < 100);
  }
  const std::size_t before = viewer->completed_heights.size();
  REQUIRE(pump_until({viewer.get()}, [&] { return viewer->completed_heights.size() > before + 5; }));  // still streaming
  harness.check_reconstructions(*viewer);
}
