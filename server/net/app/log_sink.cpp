#include "log_sink.hpp"

#include <spdlog/spdlog.h>

#include <csignal>
#include <memory>

namespace ocean::server {

std::atomic<std::uint64_t> LogSink::failed_writes_{0};

void LogSink::count_failure() {
  failed_writes_.fetch_add(1, std::memory_order_relaxed);
  std::clearerr(file_);  // the next line tries again: a restarted reader gets the log back
}

void LogSink::sink_it_(const spdlog::details::log_msg& message) {
  spdlog::memory_buf_t formatted;
  formatter_->format(message, formatted);
  if (std::fwrite(formatted.data(), 1, formatted.size(), file_) != formatted.size() || std::fflush(file_) != 0)
    count_failure();
}

void LogSink::flush_() {
  if (std::fflush(file_) != 0) count_failure();
}

void install_log_sink() {
  std::signal(SIGPIPE, SIG_IGN);
  auto logger = std::make_shared<spdlog::logger>("", std::make_shared<LogSink>());
  logger->set_level(spdlog::default_logger()->level());
  spdlog::set_default_logger(std::move(logger));
}

}  // namespace ocean::server
