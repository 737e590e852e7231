// The networked viewer: its FrameSource (a NetworkThread feeding a StreamView) run by the shared
// headless and window loops (viewer_loops.hpp), and its summary. main() only parses and picks one.
#pragma once

#include "client/viewer/viewer_exit.hpp"

#include <cstdint>
#include <string>

#include "client/viewer/network_thread.hpp"
#include "client/viewer/viewer_options.hpp"

namespace ocean::viewer {

struct ViewerSummary {
  int frames = 0;  // rendered
  double seconds = 0.0;
  double fps = 0.0;
  double kbps = 0.0;               // received bytes over the rendering time
  double cpu_ms_per_frame = 0.0;   // decode_ms_per_frame + upload_ms_per_frame
  double decode_ms_per_frame = 0.0;  // network thread CPU per rendered frame
  double upload_ms_per_frame = 0.0;  // blend + upload CPU on the render thread per rendered frame
  double latency_ms = 0.0;         // interpolation delay + half the round trip
  std::string profile;
  int grid = 0;
  std::uint64_t grid_changes = 0;
  std::uint64_t uploads = 0;
  std::uint64_t held_frames = 0;
  std::uint64_t vessels = 0, vessels_in_view = 0;  // posed, and drawn, in the last frame
  std::uint64_t timeline_stalls = 0;
  std::uint64_t frames_late = 0;
  NetworkStats net;
  std::string screenshot;
  std::string gl;
};

// Builds the network configuration from the options; false with a reason (e.g. an unknown profile).
bool make_network_config(const ViewerOptions& options, NetworkThreadConfig& config, std::string& error);

// Returns the process exit code (kExit*), with the reason in error.
int run_headless(const ViewerOptions& options, ViewerSummary& summary, std::string& error);
int run_window(const ViewerOptions& options, ViewerSummary& summary, std::string& error);

std::string summary_json(const ViewerSummary& summary);

}  // namespace ocean::viewer
