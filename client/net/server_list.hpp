// The HOST:PORT[,HOST:PORT...] value of --server, shared by every client tool (ocean-viewer,
// ocean-loadtest, ocean-admin), so all of them accept and refuse the same spellings.
#pragma once

#include <string>
#include <vector>

namespace ocean::client {

// One server to connect to: a host name or IP literal and its TCP port (a number or service name).
struct ServerEndpoint {
  std::string host;
  std::string port;
  bool operator==(const ServerEndpoint&) const = default;
};

// "host:port" or "[v6]:port", port 1..65535. False with `error` naming the entry otherwise.
bool parse_server_address(const std::string& text, ServerEndpoint& server, std::string& error);

// Every value of a (possibly repeated) --server flag, each a comma list of addresses, in order.
// Fails on the first bad entry (an empty one included: "a:1,,b:2" is a typo, not a list of two)
// and on an empty list, with `error` naming it.
bool parse_server_list(const std::vector<std::string>& values, std::vector<ServerEndpoint>& servers,
                       std::string& error);

}  // namespace ocean::client
