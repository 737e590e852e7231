// LogSink: where the server's log lines go (stdout), written so that a failed write - a pipe
// whose reader went away (`ocean-server | head`, a log shipper restarting), a full disk - is
// counted and the line dropped, never fatal: the server keeps serving without its log. SIGPIPE
// is ignored for the same reason (install_log_sink), so a write to a closed pipe returns EPIPE.
#pragma once

#include <spdlog/sinks/base_sink.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <mutex>

namespace ocean::server {

class LogSink : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit LogSink(std::FILE* file = stdout) : file_(file) {}
  static std::uint64_t failed_writes() { return failed_writes_.load(std::memory_order_relaxed); }

 protected:
  void sink_it_(const spdlog::details::log_msg& message) override;
  void flush_() override;

 private:
  void count_failure();
  std::FILE* file_;
  static std::atomic<std::uint64_t> failed_writes_;
};

// Ignores SIGPIPE and makes spdlog's default logger write through a LogSink (same pattern).
void install_log_sink();

}  // namespace ocean::server
