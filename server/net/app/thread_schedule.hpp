// ThreadSchedule: how long the calling thread has run on a CPU and how long it has waited for one,
// from the kernel's per-thread scheduler statistics (/proc/thread-self/schedstat). Admission needs
// the wait: a network thread that shares its core with another busy process is late for every
// tick without being busy, and timing its own work never shows that.
#pragma once

#include <optional>
#include <string_view>

namespace ocean::server {

struct ThreadSchedule {
  double ran_s = 0.0;     // on a CPU, since the thread started
  double waited_s = 0.0;  // runnable but waiting for a CPU, since the thread started
};

// "<ran ns> <waited ns> <timeslices>"; nullopt for anything else.
std::optional<ThreadSchedule> parse_schedstat(std::string_view text);

// The calling thread's figures; nullopt where the kernel does not keep them.
std::optional<ThreadSchedule> this_thread_schedule();

}  // namespace ocean::server
