// SessionHub: plugs a SessionCore into a Server - accepted TCP connections become TcpLinks, the
// UDP socket's datagrams and the simulation's frames reach the core with the instant they arrived,
// and an admin change reaches the simulation. It also times the network thread's work, which sets
// the core's admission limit (AdmissionBudget) and the load metrics. The core holds every rule.
// Network thread only.
#pragma once

#include "admission_budget.hpp"
#include "connect_rate.hpp"
#include "server.hpp"
#include "session_core.hpp"
#include "thread_schedule.hpp"

#include <optional>

namespace ocean::server {

class SessionHub {
 public:
  SessionHub(Server& server, SessionCoreOptions options = {});
  SessionHub(const SessionHub&) = delete;
  SessionHub& operator=(const SessionHub&) = delete;

  SessionCore& core() { return core_; }  // observers before run(); the rest only after stop()

 private:
  void on_connection(asio::ip::tcp::socket socket, const StreamTransport& transport);
  void on_frames(const std::shared_ptr<const TickFrames>& frames);
  // Adds `busy_s` of network-thread work; once a second, updates the admission limit from the
  // thread's time running and waiting for a CPU (the kernel's figures; the timed work where the
  // kernel keeps none).
  void account(double busy_s, double now_s);

  Server& server_;
  SessionCore core_;
  AdmissionBudget budget_;
  ConnectRate connect_rate_;
  Counter& connect_rate_rejects_;  // looked up once: churn at tens of thousands a second lands here
  double window_start_s_ = 0.0;
  double window_busy_s_ = 0.0;
  std::optional<ThreadSchedule> window_schedule_;  // the network thread's at the window's start
  double window_session_ticks_ = 0.0;  // sessions summed over the window's ticks
  int window_ticks_ = 0;
  std::uint64_t streams_released_ = 0;  // core_.streams_released() last seen
  std::int64_t trim_until_tick_ = -1;    // memory is handed back to the system until this tick
  double last_warning_s_ = -1e9;
};

}  // namespace ocean::server
