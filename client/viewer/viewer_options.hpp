// ViewerOptions: everything ocean-viewer's command line sets, in one plain struct, and the parsing
// of its two compound values (HOST:PORT, WIDTHxHEIGHT) with errors that name the flag.
#pragma once

#include <cstdint>
#include <string>

namespace ocean::viewer {

struct ViewerOptions {
  std::string server = "127.0.0.1:7100";  // HOST:PORT of the server's TCP listener
  std::string host = "127.0.0.1", port = "7100";
  bool headless = false;
  int frames = 0;  // 0: until closed (window) / 300 (headless)
  int width = 1280, height = 720;
  std::string screenshot;
  std::string profile;            // empty: the server's choice
  std::string transport = "udp";  // udp (falls back to tcp by itself) or tcp
  std::string record_path;        // .npy of every received frame's heights
  bool json = false;
  bool hud = false;                   // headless only; the window toggles it with H
  std::uint64_t bandwidth_bps = 0;    // asked for in the Hello; 0 = no limit stated
  double first_frame_timeout_s = 10.0;
  double interpolation_delay_s = 0.0;  // 0: three send intervals (FrameTimeline's default)
  float view_distance_m = 0.0f;
  float lod0_distance_m = 0.0f;
  float eye_height_m = 10.0f;
  float pitch_deg = -6.0f;
  float yaw_deg = 0.0f;
};

// Splits "host:port" / "[v6]:port"; false with a reason when it is not of that form.
bool parse_server_address(const std::string& text, std::string& host, std::string& port, std::string& error);
// "1280x720" -> 1280, 720; each 1..16384.
bool parse_size(const std::string& text, int& width, int& height, std::string& error);

}  // namespace ocean::viewer
