// FoamField: a whitecap's life on one patch, frame by frame (a bright phase while it breaks, then
// a remnant that fades over seconds), and remnants carried downwind and drawn out along it.
#include "client/render/foam_field.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using ocean::render::FoamField;
using ocean::render::FoamWind;

namespace {

constexpr int kN = 128;
constexpr float kPatch = 128.0f;  // 1 m samples
constexpr double kDt = 1.0 / 30.0;

// A crest folding over a 10 m x 2 m patch (long across the wind, as crests are) at (cx, cz).
std::vector<float> crest(double cx, double cz, double wind_deg) {
  std::vector<float> w(static_cast<std::size_t>(kN) * kN, 0.0f);
  const double a = wind_deg * std::numbers::pi / 180.0, ux = std::cos(a), uz = std::sin(a);
  for (int r = 0; r < kN; ++r)
    for (int c = 0; c < kN; ++c) {
      const double dx = c - cx, dz = r - cz;
      const double along = dx * ux + dz * uz, across = -dx * uz + dz * ux;
      if (std::fabs(along) <= 1.0 && std::fabs(across) <= 5.0) w[static_cast<std::size_t>(r) * kN + c] = 1.0f;
    }
  return w;
}

struct Moments {
  double sum = 0.0, peak = 0.0;
  double cx = 0.0, cz = 0.0;       // centroid
  double angle_deg = 0.0;          // the long axis, from +x towards +z
  double elongation = 1.0;         // long axis over short axis (standard deviations)
};

Moments moments(const std::vector<float>& f) {
  Moments m;
  double sx = 0, sz = 0;
  for (int r = 0; r < kN; ++r)
    for (int c = 0; c < kN; ++c) {
      const double v = f[static_cast<std::size_t>(r) * kN + c];
      m.sum += v;
      m.peak = std::max(m.peak, v);
      sx += v * c;
      sz += v * r;
    }
  if (m.sum <= 0.0) return m;
  m.cx = sx / m.sum;
  m.cz = sz / m.sum;
  double xx = 0, zz = 0, xz = 0;
  for (int r = 0; r < kN; ++r)
    for (int c = 0; c < kN; ++c) {
      const double v = f[static_cast<std::size_t>(r) * kN + c], dx = c - m.cx, dz = r - m.cz;
      xx += v * dx * dx, zz += v * dz * dz, xz += v * dx * dz;
    }
  xx /= m.sum, zz /= m.sum, xz /= m.sum;
  const double mid = 0.5 * (xx + zz), half = std::sqrt(0.25 * (xx - zz) * (xx - zz) + xz * xz);
  m.angle_deg = 0.5 * std::atan2(2.0 * xz, xx - zz) * 180.0 / std::numbers::pi;
  m.elongation = std::sqrt((mid + half) / std::max(mid - half, 1e-9));
  return m;
}

double angle_between(double a_deg, double b_deg) {  // of two axes, 0..90
  double d = std::fmod(std::fabs(a_deg - b_deg), 180.0);
  return d > 90.0 ? 180.0 - d : d;
}

}  // namespace

TEST_CASE("foam field: a whitecap is bright while it breaks and about a second after, then fades over seconds",
          "[foam]") {
  FoamField field;
  const FoamWind wind{15.0, 0.0};
  const std::vector<float> folding = crest(64, 64, 0.0), none(static_cast<std::size_t>(kN) * kN, 0.0f);
  double bright_until = -1.0, tail_until = -1.0, peak_sum = 0.0;
  for (int frame = 0; frame < 30 * 15; ++frame) {  // a 0.6 s fold, then 14.4 s of nothing
    const double t = frame * kDt;
    field.advance(kN, kPatch, kPatch, wind, kDt);
    const Moments m = moments(field.add(t < 0.6 ? folding : none));
    if (t < 0.6) peak_sum = std::max(peak_sum, m.sum);
    if (m.peak >= 0.6) bright_until = t;                  // white: the breaking foam
    if (m.sum >= 0.1 * peak_sum) tail_until = t;          // what the patch still holds
  }
  const double bright = bright_until + kDt, tail = tail_until - bright_until;
  INFO("bright " << bright << " s, then a tail of " << tail << " s");
  CHECK(bright >= 0.7);   // the fold's 0.6 s and a little after: about a second
  CHECK(bright <= 1.3);
  CHECK(tail >= 3.0);     // the tail: 3 to 10 s
  CHECK(tail <= 10.0);
}

TEST_CASE("foam field: remnants drift downwind and are drawn out along the wind", "[foam]") {
  for (const double wind_deg : {0.0, 30.0, 135.0}) {
    FoamField field;
    const FoamWind wind{20.0, wind_deg};
    const std::vector<float> folding = crest(64, 64, wind_deg), none(static_cast<std::size_t>(kN) * kN, 0.0f);
    Moments start, later;
    for (int frame = 0; frame < 30 * 4; ++frame) {  // a 0.5 s fold, then 3.5 s of drift
      field.advance(kN, kPatch, kPatch, wind, kDt);
      const Moments m = moments(field.add(frame < 15 ? folding : none));
      if (frame == 14) start = m;
      later = m;
    }
    INFO("wind " << wind_deg << " deg: axis " << start.angle_deg << " -> " << later.angle_deg << ", elongation "
                 << start.elongation << " -> " << later.elongation);
    // The fold lies across the wind; what it leaves lies along it.
    CHECK(angle_between(start.angle_deg, wind_deg + 90.0) < 10.0);
    CHECK(angle_between(later.angle_deg, wind_deg) < 20.0);
    CHECK(later.elongation > 1.5);
    // Downwind by about the surface drift: 3 % of 20 m/s over 3.5 s, 2.1 m.
    const double a = wind_deg * std::numbers::pi / 180.0;
    const double moved = (later.cx - start.cx) * std::cos(a) + (later.cz - start.cz) * std::sin(a);
    CHECK(moved == Approx(0.6 * 3.5).margin(0.5));
  }
}

TEST_CASE("foam field: a new grid starts over, and a stall does not jump", "[foam]") {
  FoamField field;
  const FoamWind wind{20.0, 0.0};
  field.advance(kN, kPatch, kPatch, wind, kDt);
  field.add(crest(64, 64, 0.0));
  CHECK(field.mean() > 0.0);
  const auto past = field.advance(kN, kPatch, kPatch, wind, 30.0);  // a 30 s stall counts as 1 s
  double sum = 0.0;
  for (float v : past) sum += v;
  CHECK(sum > 0.5 * 20.0 * FoamField::kRemnantLevel);  // the remnant after 1 s, not after 30
  const auto fresh = field.advance(64, kPatch, kPatch, wind, kDt);
  CHECK(fresh.size() == 64u * 64u);
  for (float v : fresh) CHECK(v == 0.0f);
}
