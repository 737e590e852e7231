// ocean-bench tick: the server's simulation tick (FrameProducer::produce, every offered profile's
// frame, the wake lattice included) with the config's vessels against the same config without
// them, ticks alternated in one run on one thread, so the ratio holds on a noisy machine.
// Takes ocean-server's own flags (--config FILE, --profiles, --choppiness ...).
#include "bench.hpp"

#include "config_loader.hpp"
#include "frame_producer.hpp"

#include "common/json_writer.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace {

using ocean::server::FrameProducer;
using ocean::server::ServerConfig;
using ocean::server::WakeSetup;

std::vector<const ocean::Profile*> profiles_of(const ServerConfig& config) {
  std::vector<const ocean::Profile*> out;
  for (const std::string& name : config.profiles) out.push_back(ocean::find_profile(name));
  return out;
}

std::unique_ptr<FrameProducer> producer(const ServerConfig& config, bool vessels) {
  std::string error;
  ocean::server::SceneSchedule schedule = ocean::server::make_schedule(config, error);
  if (error.empty()) error = schedule.validate();
  if (!error.empty()) throw std::invalid_argument("schedule: " + error);
  WakeSetup wake{config.wake_size_m, config.wake_origin_x_m, config.wake_origin_z_m, config.wake_decay_per_s,
                 vessels ? config.vessels : std::vector<ocean::model::VesselTrack>{}, config.tick_rate_hz};
  return std::make_unique<FrameProducer>(std::move(schedule), profiles_of(config), wake);
}

int run_tick(int argc, char** argv) {
  int ticks = 600;
  bool json = false;
  std::vector<std::string> args{"ocean-bench tick"};
  // Its own two options first; everything else is ocean-server's.
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") {
      json = true;
    } else if (a == "--ticks" && i + 1 < argc) {
      ticks = std::stoi(argv[++i]);
    } else if (a == "--help") {
      std::printf("usage: ocean-bench tick [--ticks N (600)] [--json] [ocean-server options, e.g. --config FLEET.toml]\n");
      return 0;
    } else {
      args.push_back(a);
    }
  }
  const ocean::server::ConfigLoadResult loaded = ocean::server::load_config(args);
  if (loaded.outcome != ocean::server::ConfigLoadResult::Outcome::run) {
    std::fprintf(stderr, "ocean-bench tick: %s\n", loaded.message.c_str());
    return 2;
  }
  const ServerConfig& config = loaded.config;
  if (config.vessels.empty()) {
    std::fprintf(stderr, "ocean-bench tick: the config has no [[vessel]] (give --config FLEET.toml)\n");
    return 2;
  }
  const std::unique_ptr<FrameProducer> calm_sea = producer(config, false), fleet_sea = producer(config, true);
  // Ticks a few epochs in, as a running server is: both wake parts step, one of them forced.
  const std::int64_t first = 3 * 60 * static_cast<std::int64_t>(config.tick_rate_hz);
  std::vector<double> calm_ms, fleet_ms;
  for (int i = -10; i < ticks; ++i) {  // 10 warm-up ticks
    const std::int64_t tick = first + i;
    const double time_s = static_cast<double>(tick) / config.tick_rate_hz;
    double t0 = ocean::bench::now_ms();
    (void)calm_sea->produce(tick, time_s);
    const double calm_tick = ocean::bench::now_ms() - t0;
    t0 = ocean::bench::now_ms();
    (void)fleet_sea->produce(tick, time_s);
    const double fleet_tick = ocean::bench::now_ms() - t0;
    if (i < 0) continue;
    calm_ms.push_back(calm_tick);
    fleet_ms.push_back(fleet_tick);
  }
  const double calm = ocean::bench::median(calm_ms), fleet = ocean::bench::median(fleet_ms);
  std::string profiles;
  for (const std::string& p : config.profiles) profiles += (profiles.empty() ? "" : ",") + p;
  if (json) {
    ocean::common::JsonWriter out(ocean::common::JsonWriter::Style::compact);
    out.text("bench", "tick").text("profiles", profiles).integer("vessels", static_cast<long long>(config.vessels.size()));
    out.integer("ticks", ticks).fixed("tick_ms", calm, 4).fixed("tick_vessels_ms", fleet, 4).fixed("ratio", fleet / calm, 3);
    std::printf("%s\n", out.str().c_str());
  } else {
    std::printf("tick %s: %.3f ms, with %zu vessels %.3f ms, ratio %.3f  [median of %d]\n", profiles.c_str(), calm,
                config.vessels.size(), fleet, fleet / calm, ticks);
  }
  return 0;
}

const ocean::bench::Registrar tick_bench("tick", "server tick with the config's vessels vs without (--config FLEET.toml --json)",
                                         run_tick);

}  // namespace
