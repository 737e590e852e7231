// ocean-bench fft: the decoder's fixed-point inverse 2-D FFT (CODEC.md 4), each kernel this CPU can
// run on the same data in the same run, so their ratio is measured under the same load. Also
// checks that every kernel gives the scalar kernel's bits (exit 1 if not).
#include "bench.hpp"

#include "fixed_fft.hpp"
#include "float_fft.hpp"

#include <CLI/CLI.hpp>

#include "common/json_writer.hpp"

#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using ocean::codec::FftKernel;
using ocean::codec::FixedFft;

const char* name_of(FftKernel k) { return k == FftKernel::avx2 ? "avx2" : "scalar"; }

int run_fft(int argc, char** argv) {
  std::vector<int> sizes;
  int iterations = 200;
  bool json = false;
  CLI::App app{"ocean-bench fft: the codec's int64 inverse FFT per kernel, one thread"};
  app.add_option("--size", sizes, "grid size N (N x N), repeatable; default 64 and 256");
  app.add_option("--iterations", iterations, "transforms per kernel and size")->capture_default_str();
  app.add_flag("--json", json, "one JSON object per size and kernel (the only output format)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  (void)json;
  if (sizes.empty()) sizes = {64, 256};
  int failures = 0;
  for (const int n : sizes) {
    if (n < 2 || n > 4096 || (n & (n - 1))) {
      std::fprintf(stderr, "ocean-bench fft: --size must be a power of two in [2, 4096], got %d\n", n);
      return 2;
    }
    // Decoder-sized values: a height spectrum in Q16 quanta.
    std::mt19937_64 rng(static_cast<std::uint64_t>(n));
    std::vector<std::int64_t> re(static_cast<std::size_t>(n) * n), im(re.size());
    for (auto* v : {&re, &im})
      for (auto& x : *v) x = static_cast<std::int64_t>(rng() >> 26) - (std::int64_t{1} << 37);
    std::vector<std::int64_t> scalar_re, scalar_im;
    double scalar_us = 0;
    for (const FftKernel kernel : {FftKernel::scalar, FftKernel::avx2}) {
      if (!FixedFft::kernel_available(kernel, n)) continue;
      FixedFft fft(n);
      fft.use_kernel(kernel);
      std::vector<std::int64_t> r, i;
      std::vector<double> us;
      for (int k = -3; k < iterations; ++k) {  // 3 warm-up rounds
        r = re;
        i = im;
        const double t0 = ocean::bench::now_ms();
        fft.inverse_2d(r.data(), i.data());
        if (k >= 0) us.push_back((ocean::bench::now_ms() - t0) * 1000);
      }
      const double median = ocean::bench::median(us);
      bool same = true;
      if (kernel == FftKernel::scalar) {
        scalar_re = r;
        scalar_im = i;
        scalar_us = median;
      } else {
        same = r == scalar_re && i == scalar_im;
        if (!same) ++failures;
      }
      ocean::common::JsonWriter out(ocean::common::JsonWriter::Style::compact);
      out.text("bench", "fft").integer("size", n).text("kernel", name_of(kernel)).integer("iterations", iterations);
      out.fixed("inverse_2d_us", median, 2).fixed("ns_per_butterfly", median * 1000 / (double(n) * n * __builtin_ctz(n)), 3);
      out.fixed("speedup_vs_scalar", scalar_us / median, 3).boolean("bits_match_scalar", same);
      std::printf("%s\n", out.str().c_str());
      std::fflush(stdout);
    }
    {
      ocean::codec::FloatFft fft(n);
      std::vector<float> fre(re.size()), fim(im.size()), r, i;
      for (std::size_t k = 0; k < re.size(); ++k) {
        fre[k] = static_cast<float>(static_cast<double>(re[k]));
        fim[k] = static_cast<float>(static_cast<double>(im[k]));
      }
      std::vector<double> us;
      for (int k = -3; k < iterations; ++k) {
        r = fre;
        i = fim;
        const double t0 = ocean::bench::now_ms();
        fft.inverse_2d(r.data(), i.data());
        if (k >= 0) us.push_back((ocean::bench::now_ms() - t0) * 1000);
      }
      const double median = ocean::bench::median(us);
      ocean::common::JsonWriter out(ocean::common::JsonWriter::Style::compact);
      out.text("bench", "fft").integer("size", n).text("kernel", "float32").integer("iterations", iterations);
      out.fixed("inverse_2d_us", median, 2).fixed("ns_per_butterfly", median * 1000 / (double(n) * n * __builtin_ctz(n)), 3);
      out.fixed("speedup_vs_scalar", scalar_us / median, 3);
      std::printf("%s\n", out.str().c_str());
      std::fflush(stdout);
    }
  }
  return failures ? 1 : 0;
}

const ocean::bench::Registrar fft_bench("fft", "the codec's int64 inverse FFT per kernel (scalar, AVX2)", run_fft);

}  // namespace
