// ViewerOptions: everything ocean-viewer's command line sets - the flags both viewers share
// (CommonViewerOptions) plus the network's own. --server is parsed by client::parse_server_list.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "client/viewer/viewer_flags.hpp"
#include "server_list.hpp"

namespace ocean::viewer {

struct ViewerOptions : CommonViewerOptions {
  std::vector<std::string> server;  // --server values as given: HOST:PORT[,HOST:PORT...], repeatable
  std::string host = "127.0.0.1", port = "7100";  // servers[0] when servers is set; for messages
  // Replicas to fail over between, round robin; empty = {host, port} only.
  std::vector<client::ServerEndpoint> servers;
  std::string profile;            // empty: the server's choice
  std::string transport = "udp";  // udp (falls back to tcp by itself) or tcp
  std::string record_path;        // .npy of every received frame's heights
  std::string record_hulls_path;  // CSV of every rendered frame's hull poses (HullRecord)
  std::int64_t follow_id = -1;    // >= 0: the camera follows this vessel from behind and above
  std::uint64_t bandwidth_bps = 0;    // asked for in the Hello; 0 = no limit stated
  double first_frame_timeout_s = 10.0;
  double interpolation_delay_s = 0.0;  // 0: three send intervals (FrameTimeline's default)
};

}  // namespace ocean::viewer
