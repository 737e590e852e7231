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
#include "timeline_follower.hpp"

#include <atomic>
#include <limits>
#include <memory>
#include <optional>

namespace ocean::server {

class SessionHub {
 public:
  SessionHub(Server& server, SessionCoreOptions options = {});
  ~SessionHub();
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
  // The fleet's timeline (--timeline): its follower hands entries and refusals to the network
  // thread; /readyz says not ready while the store has not answered for kTimelineStaleS, and for
  // kTimelineLateUnreadyS after an entry came after its tick.
  void follow_timeline();
  std::uint64_t read_timeline_history(const TimelineAddress& address);  // the next entry to read
  void skip_unreadable(std::uint64_t index, const std::string& reason);   // network thread (or before it runs)
  std::string timeline_readiness() const;
  bool timeline_holds(const TickFrames& frames);  // these frames must not be streamed
  void publish_timeline_metrics();

  Server& server_;
  const std::uint64_t timeline_origin_;  // this replica's mark on the timeline entries it appends
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
  std::atomic<double> late_until_s_{-1.0};  // not ready until then: an entry came after its tick
  std::uint64_t timeline_requests_needed_ = 0;  // network thread: frames that took fewer requests,
  std::uint64_t timeline_untaken_tick_ = std::numeric_limits<std::uint64_t>::max();  // from this tick, are held
  std::unique_ptr<TimelineFollower> timeline_;  // last: stopped before anything its handlers reach
};

// A replica whose timeline store has not answered a read for this long says it is not ready: an
// entry appended meanwhile could take effect before this replica reads it (the lead is 1 s).
inline constexpr double kTimelineStaleS = 0.5;
// After an entry read past its tick, a replica says it is not ready this long (its viewers' keys).
inline constexpr double kTimelineLateUnreadyS = 2.0;
// A replica that cannot read the timeline within this long at its start exits (status 1).
inline constexpr double kTimelineStartS = 10.0;

}  // namespace ocean::server
