// ServerProcess: one real ocean-server of the build tree, started with given arguments, its
// output going to a log file (so a full pipe can never stall it), its TCP port read from its
// "listening tcp=..." line. Killed with SIGKILL when destroyed, or on purpose by kill(), and by
// the kernel if the test process dies first (PR_SET_PDEATHSIG), so no server outlives a crash.
#pragma once

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <optional>
#include <sys/prctl.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace ocean::replica_test {

class ServerProcess {
 public:
  ServerProcess(std::vector<std::string> args, std::string log_path) : log_path_(std::move(log_path)) {
    const char* build = std::getenv("OCEAN_BUILD_DIR");
    args.insert(args.begin(), std::string(build ? build : ".") + "/server/ocean-server");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    INFO("log file " << log_path_);
    REQUIRE(log_fd >= 0);
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0) {
      // The child of a threaded process: async-signal-safe calls only, until execv.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(127);  // the parent died before prctl took effect
      ::dup2(log_fd, 1);
      ::dup2(log_fd, 2);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(log_fd);
    INFO("fork for " << args.front());
    REQUIRE(pid_ > 0);
  }
  ~ServerProcess() { kill(); }
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  // Waits for the "listening" line and returns the TCP port; nullopt if the process exited or
  // said nothing of the sort within `seconds` (log() then tells why).
  std::optional<std::uint16_t> wait_listening(double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      if (const std::optional<std::uint16_t> port = listening_port(log())) return port;
      if (exited()) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return std::nullopt;
  }

  // SIGKILL: no Bye, no FIN from the application; the kernel closes its sockets.
  void kill() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

  bool exited() {
    if (pid_ <= 0) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
    pid_ = -1;
    return true;
  }

  // "listening tcp=127.0.0.1:41234 udp=..." -> 41234.
  static std::optional<std::uint16_t> listening_port(const std::string& text) {
    const std::size_t line = text.find("listening tcp=");
    if (line == std::string::npos) return std::nullopt;
    const std::size_t end = text.find(' ', line + 14);
    const std::size_t colon = text.rfind(':', end);
    if (end == std::string::npos || colon == std::string::npos || colon < line) return std::nullopt;
    const std::string digits = text.substr(colon + 1, end - colon - 1);
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    const int port = std::stoi(digits);
    if (port <= 0 || port > 65535) return std::nullopt;
    return static_cast<std::uint16_t>(port);
  }

  std::string log() const {
    std::ifstream in(log_path_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  std::string log_path_;
  pid_t pid_ = -1;
};

}  // namespace ocean::replica_test
