// KbpsMeter: the HUD's received rate follows a steady stream and survives a byte counter that
// starts again (a reconnect) without reading the unsigned wrap-around as ~10^13 kbit/s.
#include <catch2/catch.hpp>

#include "client/viewer/kbps_meter.hpp"

using ocean::viewer::KbpsMeter;

TEST_CASE("a steady stream converges on its rate") {
  KbpsMeter meter;
  CHECK(meter.update(0, 1.0) == 0.0);  // the first sample only sets the baseline
  std::uint64_t bytes = 0;
  for (int i = 1; i <= 40; ++i) meter.update(bytes += 2500, 1.0 + 0.2 * i);  // 12.5 kB/s = 100 kbit/s
  CHECK(meter.kbps() == Approx(100.0).epsilon(0.01));
}

TEST_CASE("a counter that starts again is a new baseline, not a wrapped difference") {
  KbpsMeter meter;
  std::uint64_t bytes = 1'000'000;
  double t = 1.0;
  meter.update(bytes, t);
  for (int i = 0; i < 20; ++i) meter.update(bytes += 2500, t += 0.2);
  const double before = meter.kbps();
  CHECK(meter.update(1000, t += 0.2) == before);  // restarted: no sample
  bytes = 1000;
  for (int i = 0; i < 20; ++i) {
    const double kbps = meter.update(bytes += 2500, t += 0.2);
    CHECK(kbps >= 0.0);
    CHECK(kbps < 1000.0);
  }
  CHECK(meter.kbps() == Approx(100.0).epsilon(0.01));
}

TEST_CASE("samples at the same time or earlier do not divide by zero") {
  KbpsMeter meter;
  meter.update(0, 2.0);
  CHECK(meter.update(5000, 2.0) == 0.0);
  CHECK(meter.update(9000, 1.5) == 0.0);
  CHECK(meter.update(11500, 1.7) > 0.0);
}
