// A client's downlink rate (ReceiveRate: busiest second, calm rate) and the run's first-frame and rate figures.
#include <catch2/catch.hpp>

#include "client_figures.hpp"
#include "receive_rate.hpp"

using namespace ocean::loadtest;

namespace {
// Samples every 100 ms from t0 for `seconds`, `bytes_per_s` arriving evenly; returns the bytes.
std::uint64_t feed(ReceiveRate& p, double t0, double seconds, double bytes_per_s, std::uint64_t bytes) {
  for (int k = 1; k <= static_cast<int>(seconds * 10 + 0.5); ++k) {
    bytes += static_cast<std::uint64_t>(bytes_per_s * 0.1);
    p.sample(t0 + k * 0.1, bytes);
  }
  return bytes;
}
}  // namespace

TEST_CASE("peak rate: a steady stream peaks at its own rate") {
  ReceiveRate p;
  p.sample(0.0, 0);
  p.set_first_frame(0.0);
  feed(p, 0.0, 5.0, 4000, 0);  // 32 kbit/s
  CHECK(p.has_steady_window());
  CHECK(p.peak_kbps() == Approx(32.0));
  CHECK(p.startup_peak_kbps() == 0.0);
}

TEST_CASE("peak rate: a burst counts whole in the one second that holds it") {
  ReceiveRate p;
  p.sample(0.0, 0);
  p.set_first_frame(0.0);
  std::uint64_t b = feed(p, 0.0, 2.0, 4000, 0);
  b += 10000;  // a 10 kB keyframe in one 100 ms bucket
  p.sample(2.1, b);
  feed(p, 2.1, 3.0, 4000, b);
  CHECK(p.peak_kbps() == Approx((10000 + 4000) * 8 / 1000.0).epsilon(0.05));
}

TEST_CASE("peak rate: the startup keyframe shows as startup, not as the steady peak") {
  ReceiveRate p;
  p.sample(0.0, 0);
  p.sample(0.4, 200);     // handshake
  p.sample(0.8, 20200);   // keyframe
  p.set_first_frame(0.8);
  feed(p, 0.8, 4.0, 2000, 20200);
  CHECK(p.startup_peak_kbps() >= 20000 * 8 / 1000.0);
  CHECK(p.peak_kbps() == Approx(16.0).epsilon(0.05));
}

TEST_CASE("peak rate: a client that never got a frame has only startup windows") {
  ReceiveRate p;
  p.sample(0.0, 0);
  feed(p, 0.0, 3.0, 1000, 0);
  CHECK_FALSE(p.has_steady_window());
  CHECK(p.startup_peak_kbps() == Approx(8.0).epsilon(0.05));
}

TEST_CASE("peak rate: a late sample does not stretch a window beyond a second") {
  ReceiveRate p;
  p.sample(0.0, 0);
  p.set_first_frame(0.0);
  p.sample(0.1, 100);
  p.sample(2.6, 30100);  // the loop stalled 2.5 s: 30 kB over 2.5 s is 12 kB/s, not 30 kB in one second
  CHECK(p.peak_kbps() <= 30000 * 8 / 1000.0 / 2.5 + 1e-9);
}

TEST_CASE("connection figures: first frame and peaks over the clients that had them") {
  std::vector<ClientConnectionFacts> c(4);
  c[0].ttff_s = 0.5;
  c[0].peak_kbps = 40;
  c[0].startup_peak_kbps = 90;
  c[1].ttff_s = 1.5;
  c[1].peak_kbps = 60;
  c[2].ttff_s = 0.9;
  c[2].peak_kbps = 50;
  c[0].calm_kbps = 30;
  c[1].calm_kbps = 20;
  c[3].startup_peak_kbps = 120;  // never got a frame
  const ConnectionFigures f = connection_figures(c);
  CHECK(f.clients_without_frame == 1);
  CHECK(*f.ttff_max_s == 1.5);
  // Medians are read from mergeable histograms: the upper edge of the value's bin.
  CHECK(*f.ttff_p50_s == Approx(0.9).margin(ConnectionParts::kTtffBinS));
  CHECK(f.kbps_peak_1s == 60);
  CHECK(f.kbps_peak_1s_p50 == Approx(50).margin(ConnectionParts::kKbpsBin));
  CHECK(f.kbps_peak_1s_startup == 120);
  CHECK(f.kbps_calm == Approx(20).margin(ConnectionParts::kKbpsBin));

  const ConnectionFigures none = connection_figures(std::vector<ClientConnectionFacts>(3));
  CHECK(none.clients_without_frame == 3);
  CHECK_FALSE(none.ttff_max_s);
  CHECK_FALSE(none.ttff_p50_s);
}

TEST_CASE("receive rate: calm is the stream between bursts, untouched by a keyframe every 2.5 s") {
  ReceiveRate p;
  p.sample(0.0, 0);
  p.sample(0.5, 15000);  // startup keyframe: not steady
  p.set_first_frame(0.5);
  CHECK_FALSE(p.calm_kbps());
  std::uint64_t b = 15000;
  for (int k = 1; k <= 100; ++k) {
    b += 500 + (k % 25 == 0 ? 15000 : 0);  // 40 kbit/s, and a re-key every 2.5 s
    p.sample(0.5 + k * 0.1, b);
  }
  REQUIRE(p.calm_kbps());
  CHECK(*p.calm_kbps() == Approx(40.0));
  CHECK(p.peak_kbps() == Approx(40.0 + 120.0).epsilon(0.05));
}
