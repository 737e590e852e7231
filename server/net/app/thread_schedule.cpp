#include "thread_schedule.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>

namespace ocean::server {

namespace {

bool next_number(std::string_view& text, std::uint64_t& value) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end == text.data()) return false;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return true;
}

}  // namespace

std::optional<ThreadSchedule> parse_schedstat(std::string_view text) {
  std::uint64_t ran_ns = 0, waited_ns = 0, slices = 0;
  if (!next_number(text, ran_ns) || !next_number(text, waited_ns) || !next_number(text, slices)) return std::nullopt;
  while (!text.empty() && (text.front() == ' ' || text.front() == '\n')) text.remove_prefix(1);
  if (!text.empty()) return std::nullopt;
  return ThreadSchedule{static_cast<double>(ran_ns) * 1e-9, static_cast<double>(waited_ns) * 1e-9};
}

std::optional<ThreadSchedule> this_thread_schedule() {
  // Read once a second on the network thread: a small file, no allocation beyond the FILE.
  std::FILE* file = std::fopen("/proc/thread-self/schedstat", "r");
  if (file == nullptr) return std::nullopt;
  char buffer[128];
  const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
  std::fclose(file);
  if (n == 0 || n == sizeof buffer) return std::nullopt;
  return parse_schedstat(std::string_view(buffer, n));
}

}  // namespace ocean::server
