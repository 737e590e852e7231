#include "server_process.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <poll.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace ocean::faults {
namespace {

std::string server_binary() {
  const char* build = std::getenv("OCEAN_BUILD_DIR");
  return std::string(build ? build : ".") + "/server/ocean-server";
}

// The port after "key=HOST:" in the listening line.
std::uint16_t port_after(const std::string& line, const std::string& key) {
  const auto at = line.find(key + "=");
  if (at == std::string::npos) return 0;
  const auto end = line.find_first_of(" \n", at);
  const std::string endpoint = line.substr(at, end - at);
  const auto colon = endpoint.rfind(':');
  return colon == std::string::npos ? 0 : static_cast<std::uint16_t>(std::atoi(endpoint.c_str() + colon + 1));
}

}  // namespace

ServerProcess::ServerProcess(const std::vector<std::string>& extra_args) {
  std::vector<std::string> args{server_binary(), "--listen", "127.0.0.1:0", "--metrics-listen", "127.0.0.1:0"};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int spawned = ::posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  read_fd_ = fds[0];
  if (spawned != 0) {
    pid_ = -1;
    ::close(read_fd_);
    throw std::runtime_error("cannot spawn " + args[0] + " (set OCEAN_BUILD_DIR)");
  }
  drainer_ = std::thread([this] { drain_output(); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    {
      std::lock_guard lock(mutex_);
      const auto at = log_.find("listening tcp=");
      if (at != std::string::npos && log_.find('\n', at) != std::string::npos) {
        const std::string line = log_.substr(at, log_.find('\n', at) - at);
        tcp_port_ = port_after(line, "tcp");
        metrics_port_ = port_after(line, "metrics");
        break;
      }
    }
    if (!alive()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (tcp_port_ == 0 || metrics_port_ == 0) {
    const std::string output = log();
    shutdown();
    throw std::runtime_error("ocean-server did not report its ports; output:\n" + output);
  }
}

ServerProcess::~ServerProcess() { shutdown(); }

void ServerProcess::shutdown() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  stop_ = true;
  if (drainer_.joinable()) drainer_.join();
  if (read_fd_ >= 0) ::close(read_fd_);
  read_fd_ = -1;
}

void ServerProcess::drain_output() {
  char buffer[8192];
  while (!stop_) {
    pollfd p{read_fd_, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    const ssize_t n = ::read(read_fd_, buffer, sizeof buffer);
    if (n <= 0) return;
    std::lock_guard lock(mutex_);
    // Keep the log bounded: a reconnect storm logs a line per connection.
    if (log_.size() > (8u << 20)) log_.erase(0, log_.size() / 2);
    log_.append(buffer, static_cast<std::size_t>(n));
  }
}

bool ServerProcess::alive() const {
  if (pid_ <= 0) return false;
  int status = 0;
  return ::waitpid(pid_, &status, WNOHANG) == 0;
}

std::optional<std::uint64_t> ServerProcess::rss_kib() const {
  std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10);
  return std::nullopt;
}

std::string ServerProcess::log() const {
  std::lock_guard lock(mutex_);
  return log_;
}

}  // namespace ocean::faults
