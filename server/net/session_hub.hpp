// SessionHub: plugs a SessionCore into a Server - accepted TCP connections become TcpLinks, the
// UDP socket's datagrams and the simulation's frames reach the core with the instant they arrived,
// and an admin change reaches the simulation. The core holds every rule; this holds the wiring.
// Network thread only.
#pragma once

#include "server.hpp"
#include "session_core.hpp"

namespace ocean::server {

class SessionHub {
 public:
  SessionHub(Server& server, SessionCoreOptions options = {});
  SessionHub(const SessionHub&) = delete;
  SessionHub& operator=(const SessionHub&) = delete;

  SessionCore& core() { return core_; }  // observers before run(); the rest only after stop()

 private:
  void on_connection(asio::ip::tcp::socket socket);

  Server& server_;
  SessionCore core_;
};

}  // namespace ocean::server
