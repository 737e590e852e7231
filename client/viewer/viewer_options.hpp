// ViewerOptions: everything ocean-viewer's command line sets - the flags both viewers share
// (CommonViewerOptions) plus the network's own - and the parse of its HOST:PORT value.
#pragma once

#include <cstdint>
#include <string>

#include "client/viewer/viewer_flags.hpp"

namespace ocean::viewer {

struct ViewerOptions : CommonViewerOptions {
  std::string server = "127.0.0.1:7100";  // HOST:PORT of the server's TCP listener
  std::string host = "127.0.0.1", port = "7100";
  std::string profile;            // empty: the server's choice
  std::string transport = "udp";  // udp (falls back to tcp by itself) or tcp
  std::string record_path;        // .npy of every received frame's heights
  std::uint64_t bandwidth_bps = 0;    // asked for in the Hello; 0 = no limit stated
  double first_frame_timeout_s = 10.0;
  double interpolation_delay_s = 0.0;  // 0: three send intervals (FrameTimeline's default)
};

// Splits "host:port" / "[v6]:port"; false with a reason when it is not of that form.
bool parse_server_address(const std::string& text, std::string& host, std::string& port, std::string& error);

}  // namespace ocean::viewer
