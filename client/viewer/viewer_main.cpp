// ocean-viewer: renders the sea an ocean-server streams, in a window or headless.
//   ocean-viewer --server 127.0.0.1:7100                         window (W/S/A/D, drag, F, H, Q/Esc)
//   ocean-viewer --server 127.0.0.1:7100 --headless --frames 300 --size 1280x720 --screenshot out.png --json
#include <cstdio>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "client/viewer/viewer_options.hpp"
#include "client/viewer/viewer_run.hpp"

int main(int argc, char** argv) {
  ocean::viewer::ViewerOptions o;
  std::string size = "1280x720";
  CLI::App app{"Render the ocean an ocean-server streams, with the GLES 2 renderer"};
  app.add_option("--server", o.server, "HOST:PORT of the server's TCP listener")->required();
  app.add_flag("--headless", o.headless, "render off-screen through EGL, no window");
  app.add_option("--frames", o.frames, "frames to render, then exit (headless default 300)")->check(CLI::Range(0, 10000000));
  app.add_option("--size", size, "WIDTHxHEIGHT in pixels");
  app.add_option("--screenshot", o.screenshot, "write the last rendered frame to this PNG");
  app.add_option("--profile", o.profile, "stream profile to ask for (mobile, desktop, desktop-choppy, lite)");
  app.add_option("--transport", o.transport, "udp (falls back to tcp when UDP fails) or tcp")
      ->check(CLI::IsMember({"udp", "tcp"}));
  app.add_option("--record", o.record_path, "write the heights of every received frame to this .npy");
  app.add_flag("--json", o.json, "print one JSON summary {frames, fps, kbps, cpu_ms_per_frame, ...}");
  app.add_option("--bandwidth", o.bandwidth_bps, "link bandwidth to tell the server, bits per second (0 = unstated)");
  app.add_flag("--hud", o.hud, "draw the HUD in headless mode too");
  app.add_option("--first-frame-timeout", o.first_frame_timeout_s, "headless: seconds to wait for the first frame")
      ->check(CLI::Range(0.1, 3600.0));
  app.add_option("--interpolation-delay", o.interpolation_delay_s,
                 "seconds to render behind the newest frame (0 = three send intervals)")
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--view-distance", o.view_distance_m, "metres to draw tiles out to (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--lod0", o.lod0_distance_m, "full-detail radius, metres (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--eye-height", o.eye_height_m, "camera height above sea level, metres")->check(CLI::Range(1.0f, 10000.0f));
  app.add_option("--pitch", o.pitch_deg, "camera pitch, degrees (negative looks down)")->check(CLI::Range(-89.0f, 89.0f));
  app.add_option("--yaw", o.yaw_deg, "camera yaw, degrees (positive turns left)");
  CLI11_PARSE(app, argc, argv);

  std::string error;
  if (!ocean::viewer::parse_server_address(o.server, o.host, o.port, error) ||
      !ocean::viewer::parse_size(size, o.width, o.height, error)) {
    std::fprintf(stderr, "ocean-viewer: %s\n", error.c_str());
    return 2;
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
