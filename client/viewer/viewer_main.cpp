// ocean-viewer: renders the sea an ocean-server streams, in a window or headless.
//   ocean-viewer --server 127.0.0.1:7100                         window (W/S/A/D, drag, F, H, Q/Esc)
//   ocean-viewer --server 10.0.0.1:7100,10.0.0.2:7100             fail over between replicas
//   ocean-viewer --server 127.0.0.1:7100 --headless --frames 300 --size 1280x720 --screenshot out.png --json
#include <cstdio>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "client/viewer/viewer_options.hpp"
#include "client/viewer/viewer_run.hpp"
#include "profile.hpp"

namespace {

// "mobile, desktop, ...": the profile table's names, for --profile's help.
std::string profile_names() {
  std::string names;
  for (const ocean::Profile& p : ocean::all_profiles()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

// Every flag ocean-viewer takes, its help and checks, and the exit codes' table.
void add_viewer_flags(CLI::App& app, ocean::viewer::ViewerOptions& o) {
  app.add_option("--server", o.server,
                 "HOST:PORT of the server's TCP listener; a comma list (or the flag repeated) names replicas to "
                 "fail over to, round robin")
      ->required();
  ocean::viewer::add_output_flags(
      app, o, {300, 10000000, "print one JSON summary {frames, fps, kbps, cpu_ms_per_frame, ...}; its kbps is every byte received over the whole run, "
       "keyframe included (the HUD's kbit/s is the last second's rate)"});
  app.add_option("--profile", o.profile, "stream profile to ask for (" + profile_names() + ")");
  app.add_option("--transport", o.transport, "udp (falls back to tcp when UDP fails) or tcp")
      ->check(CLI::IsMember({"udp", "tcp"}));
  app.add_option("--record", o.record_path, "write every received frame: heights to this .npy, ticks and every channel of every lattice beside it (CODEC.md 10)");
  app.add_option("--record-hulls", o.record_hulls_path,
                 "write every rendered frame's hull poses (heave, pitch, roll) and the decoded surface under each hull to this CSV");
  app.add_option("--follow", o.follow_id, "follow vessel ID from behind and above (the window's V key cycles the vessels)")
      ->check(CLI::Range(0ll, 4294967295ll));
  app.add_option("--bandwidth", o.bandwidth_bps, "link bandwidth to tell the server, bits per second (0 = unstated)");
  app.add_option("--first-frame-timeout", o.first_frame_timeout_s, "headless: seconds to wait for the first frame")
      ->check(CLI::Range(0.1, 3600.0));
  app.add_option("--interpolation-delay", o.interpolation_delay_s,
                 "seconds to render behind the newest frame (0 = three send intervals)")
      ->check(CLI::Range(0.0, 10.0));
  ocean::viewer::add_camera_flags(app, o);
  app.footer(ocean::viewer::kExitTable);
}

}  // namespace

int main(int argc, char** argv) {
  ocean::viewer::ViewerOptions o;
  CLI::App app{"Render the ocean an ocean-server streams, with the GLES 2 renderer"};
  add_viewer_flags(app, o);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ocean-viewer: %s\n", e.what());
    return ocean::viewer::kExitUsage;
  }

  std::string error;
  if (ocean::client::parse_server_list(o.server, o.servers, error)) {
    o.host = o.servers.front().host;
    o.port = o.servers.front().port;
  }
  if (!error.empty() || !ocean::viewer::parse_size(o.size, o.width, o.height, error)) {
    std::fprintf(stderr, "ocean-viewer: %s\n", error.c_str());
    return ocean::viewer::kExitUsage;
  }
  if (!o.headless && !std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
    std::fprintf(stderr, "ocean-viewer: no DISPLAY set, rendering headless (pass --headless to silence this)\n");
    o.headless = true;
  }
  ocean::viewer::ViewerSummary summary;
  int code = 1;
  try {
    code = o.headless ? ocean::viewer::run_headless(o, summary, error) : ocean::viewer::run_window(o, summary, error);
  } catch (const std::exception& e) {
    error = e.what();
    code = 1;
  }
  if (code != 0) {
    std::fprintf(stderr, "ocean-viewer: %s\n", error.c_str());
    return code;
  }
  if (!summary.net.record_error.empty()) std::fprintf(stderr, "ocean-viewer: --record: %s\n", summary.net.record_error.c_str());
  if (o.json) std::printf("%s\n", ocean::viewer::summary_json(summary).c_str());
  return summary.net.record_error.empty() ? 0 : 1;
}
