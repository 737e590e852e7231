// Desktop viewers joining one after another (issue 15): each desktop key root costs a 256 x 256
// synthesis a tick on the network thread, and ten of them 0.6 s apart once took the mobile
// viewers, /healthz and the server's memory down with them. The joiners here read their frames
// but decode nothing (the server's cost does not depend on it, and decoding ten desktop streams
// would load this machine's cores, not the server).
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "fault_scenario.hpp"
#include "message_builders.hpp"
#include "raw_peers.hpp"

using namespace ocean::faults;
namespace proto = ocean::protocol;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

// A desktop viewer over TCP that drains its frames and pings so the idle limit never ends it.
class DesktopReader {
 public:
  DesktopReader(std::uint16_t port, int index) : tcp_(port) {
    welcome_ = tcp_.handshake(proto::Hello{kDesktop, 0, ocean::wire::Transport::tcp, "desktop-" + std::to_string(index)});
    if (welcome_) thread_ = std::thread([this] { run(); });
  }
  ~DesktopReader() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  bool welcomed() const { return welcome_.has_value(); }
  std::uint64_t frames() const { return frames_; }

 private:
  void run() {
    lower_thread_priority();
    auto next_ping = Clock::now();
    std::uint32_t seq = 0;
    while (!stop_) {
      if (Clock::now() >= next_ping) {
        tcp_.send(proto::encode(proto::Ping{welcome_->session_id, {}, ++seq, 0}));
        next_ping = Clock::now() + milliseconds(2000);
      }
      if (const auto message = tcp_.read_message(0.1); message && std::holds_alternative<proto::FrameData>(*message))
        ++frames_;
    }
  }
  RawTcp tcp_;
  std::optional<proto::Welcome> welcome_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> frames_{0};
  std::thread thread_;
};

}  // namespace

TEST_CASE("ten desktop viewers joining 0.6 s apart leave the mobile viewers on time and the server responsive",
          "[faults]") {
  if (!kTimingMeasurable) {
    // Under a sanitizer the desktop encodes run several times slower: the server cannot keep up,
    // admission refuses the joiners, and nothing here would measure the server.
    WARN("skipped under a sanitizer: it measures the server's timing and memory");
    return;
  }
  FaultScenario s({"--profiles", "mobile,desktop", "--max-clients", "64"});
  start_population(s);
  const std::uint64_t rss_before = s.server().rss_kib().value_or(0);

  std::atomic<bool> probing{true};
  std::atomic<double> slowest_health_s{0.0};
  std::atomic<int> health_failures{0};
  std::thread prober([&] {
    while (probing) {
      const auto start = Clock::now();
      const auto reply = http_get(s.server().metrics_port(), "/healthz", 1.0);
      const double took = std::chrono::duration<double>(Clock::now() - start).count();
      if (!reply || reply->status != 200) ++health_failures;
      slowest_health_s = std::max(slowest_health_s.load(), took);
      std::this_thread::sleep_for(milliseconds(100));
    }
  });
  std::vector<std::unique_ptr<DesktopReader>> desktops;
  const FaultMeasure joins = s.measure("ten desktop joins", [&] {
    for (int i = 0; i < 10; ++i) {
      desktops.push_back(std::make_unique<DesktopReader>(s.port(), i));
      std::this_thread::sleep_for(milliseconds(600));
    }
    std::this_thread::sleep_for(milliseconds(2500));  // every joiner past a merge age with its key
  });
  probing = false;
  prober.join();
  const std::string metrics = s.metrics();
  const double lag_p99 = metric_value(metrics, "ocean_loop_lag_seconds{quantile=\"0.99\"}").value_or(1e9);
  const double merges = metric_value(metrics, "ocean_key_root_merges_total").value_or(0.0);
  const double deferred = metric_value(metrics, "ocean_keys_deferred_roots_total").value_or(0.0);
  std::printf("[faults] desktop joins: loop lag p99 %.1f ms, /healthz slowest %.1f ms (%d failed), %.0f root merges, "
              "%.0f key ticks deferred\n",
              1e3 * lag_p99, 1e3 * slowest_health_s.load(), health_failures.load(), merges, deferred);
  std::size_t welcomed = 0;
  std::uint64_t fewest_frames = ~0ull;
  for (const auto& desktop : desktops)
    if (desktop->welcomed()) {
      ++welcomed;
      fewest_frames = std::min(fewest_frames, desktop->frames());
    }
  std::printf("[faults] desktop joins: %zu of 10 welcomed, the fewest frames any got %llu\n", welcomed,
              static_cast<unsigned long long>(fewest_frames));
  CHECK(welcomed >= 1);
  CHECK(health_failures == 0);
  check_population(s, joins);
  // A machine too busy to keep the unattacked server's clients on time (or a sanitizer) slows the
  // server enough for admission to refuse joiners: then only the above is asserted.
  if (machine_kept_up(joins)) {
    CHECK(welcomed == 10);
    CHECK(fewest_frames >= 30);          // streaming, not only keyed, the last joiner included
    CHECK(lag_p99 <= 1.0 / 30.0);        // no tick served later than one period
    CHECK(slowest_health_s <= 0.1);
  }

  desktops.clear();
  // The released stream's states go at once, the closing sessions' buffers over the next seconds.
  std::uint64_t rss_after = 0;
  for (int i = 0; i < 16; ++i) {
    std::this_thread::sleep_for(milliseconds(500));
    rss_after = s.server().rss_kib().value_or(0);
    if (static_cast<double>(rss_after) <= 1.2 * static_cast<double>(rss_before)) break;
  }
  std::printf("[faults] desktop joins: server RSS %llu KiB before, peak %llu, %llu after they left\n",
              static_cast<unsigned long long>(rss_before), static_cast<unsigned long long>(joins.rss_peak_kib),
              static_cast<unsigned long long>(rss_after));
  CHECK(static_cast<double>(rss_after) <= 1.2 * static_cast<double>(rss_before));  // sanitizers returned above
}
