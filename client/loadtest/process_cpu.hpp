// CPU seconds used so far, by this process and by another one (a local server) read from /proc.
#pragma once

#include <optional>

namespace ocean::loadtest {

double own_cpu_s();  // user + system, getrusage
// utime + stime of process `pid` from /proc/PID/stat; nullopt when it cannot be read (or pid <= 0).
std::optional<double> process_cpu_s(int pid);

}  // namespace ocean::loadtest
