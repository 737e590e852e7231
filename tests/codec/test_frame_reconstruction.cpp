// The decoder shows a frame from its synthesis before rounding plus its corrections, in one pass;
// the encoder promises the floats of the integer path (round, correct, convert). The two must give
// the same bits for any synthesis and any corrections a hostile stream can carry: values beyond 32
// and 51 bits, NaN, a sample corrected twice, corrections in any order, on every lattice.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "float_bits.hpp"
#include "field_conversion.hpp"
#include "frame_reconstruction.hpp"
#include "modal_model.hpp"
#include "stream_config.hpp"

using namespace ocean::codec;

namespace {

// A 64 tile and a coarser 32 lattice, every channel.
StreamConfig two_lattices() {
  StreamConfig c;
  c.grid = 64;
  c.rate_hz = 30;
  c.normals = true;
  c.choppy = true;
  c.cascades = {{1, 64, {4, 0}}, {8, 32, {0, 16}}};
  return c;
}

float any_value(std::mt19937_64& rng) {
  switch (rng() % 16) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return (rng() % 2 ? 1.0f : -1.0f) * std::numeric_limits<float>::infinity();
    case 2: return std::ldexp(rng() % 2 ? 1.0f : -1.0f, 31 + 24) * (1.0f + static_cast<float>(rng() % 3) / 8);
    default: {
      const float mantissa = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng);
      return std::ldexp(mantissa, static_cast<int>(rng() % 90) - 20);
    }
  }
}

using ocean::codec::test::same_bits;

}  // namespace

TEST_CASE("a frame converted before rounding equals the rounded, corrected frame, bit for bit", "[reconstruction]") {
  const StreamConfig config = two_lattices();
  const std::vector<StreamConfig::Lattice> lattices = config.lattices();
  const std::size_t samples = config.samples();
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    UnroundedFields unrounded;
    for (auto& ch : unrounded.channels) {
      ch.resize(samples);
      for (float& v : ch) v = any_value(rng);
    }
    // Corrections as chunks deliver them: each chunk's list sorted by position, the lists appended,
    // so a sample may come twice and the whole is not in order; values up to the 32-bit limits.
    Corrections corrections;
    for (int chunk = 0; chunk < 3; ++chunk)
      for (int ch = 0; ch < kCorrectionChannels; ++ch) {
        std::vector<Correction> list;
        for (int k = 0; k < 60; ++k) {
          const std::int32_t value = rng() % 4 ? static_cast<std::int32_t>(rng() % 201) - 100
                                               : static_cast<std::int32_t>(static_cast<std::uint32_t>(rng()));
          list.push_back({static_cast<std::uint32_t>(rng() % samples), value == 0 ? 1 : value});
        }
        std::sort(list.begin(), list.end(), [](const Correction& a, const Correction& b) { return a.pos < b.pos; });
        auto& all = corrections[ch];
        all.insert(all.end(), list.begin(), list.end());
      }

    SampleFields rounded;
    for (int ch = 0; ch < kCorrectionChannels; ++ch) {
      rounded[ch].resize(samples);
      for (const StreamConfig::Lattice& l : lattices)
        round_fields(unrounded.channels[ch].data() + l.samples_at, static_cast<std::size_t>(l.n) * l.n,
                     synthesis_scale(l.n), rounded[ch].data() + l.samples_at);
    }
    apply_corrections(rounded, corrections);
    ReconstructedFrame want, one_pass, spread;
    to_float(rounded, config, want);
    to_float(unrounded, corrections, config, one_pass);
    // Parts run in reverse order, as threads may.
    const ParallelFor reversed = [](int count, const std::function<void(int)>& job) {
      for (int i = count - 1; i >= 0; --i) job(i);
    };
    to_float(unrounded, corrections, config, spread, reversed);
    INFO("trial " << trial);
    for (const ReconstructedFrame* got : {&one_pass, &spread}) {
      CHECK(same_bits(got->height, want.height));
      CHECK(same_bits(got->slope_x, want.slope_x));
      CHECK(same_bits(got->slope_z, want.slope_z));
      CHECK(same_bits(got->disp_x, want.disp_x));
      CHECK(same_bits(got->disp_z, want.disp_z));
      CHECK(same_bits(got->disp_xx, want.disp_xx));
      CHECK(same_bits(got->disp_zz, want.disp_zz));
      CHECK(same_bits(got->disp_xz, want.disp_xz));
      CHECK(same_bits(got->jacobian, want.jacobian));
    }
  }
}

TEST_CASE("synthesis before rounding rounds to the integer synthesis", "[reconstruction]") {
  const StreamConfig config = two_lattices();
  ModalModel model(config);
  std::mt19937_64 rng(23);
  HalfSpectrum cur;
  for (auto* v : {&cur.re, &cur.im}) {
    v->resize(static_cast<std::size_t>(model.half_size()));
    for (std::int64_t& x : *v) x = static_cast<std::int64_t>(rng() >> 28) - (std::int64_t{1} << 35);
  }
  for (double choppiness : {1.2, 0.0}) {
    SampleFields rounded;
    UnroundedFields unrounded;
    model.synthesize(cur, choppiness, rounded);
    model.synthesize(cur, choppiness, unrounded);
    INFO("choppiness " << choppiness);
    for (int ch = 0; ch < kCorrectionChannels; ++ch) {
      REQUIRE(unrounded.channels[ch].size() == rounded[ch].size());
      std::size_t mismatches = 0;
      for (const StreamConfig::Lattice& l : config.lattices())
        for (std::size_t i = l.samples_at; i < l.samples_at + static_cast<std::size_t>(l.n) * l.n; ++i)
          mismatches += round_field(unrounded.channels[ch][i], synthesis_scale(l.n)) != rounded[ch][i];
      CHECK(mismatches == 0);
    }
    std::int64_t largest = 0;
    for (std::int64_t v : rounded[ocean::ChannelId::disp_x]) largest = std::max(largest, v < 0 ? -v : v);
    CHECK((choppiness == 0.0 ? largest == 0 : largest > 0));
  }
}
