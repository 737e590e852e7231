#include "server_process.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace ocean::test_support {
namespace {

using Clock = std::chrono::steady_clock;

Clock::time_point deadline_after(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// "key=HOST:PORT" within `line` -> PORT; 0 for "key=off"; nullopt when missing or malformed.
std::optional<std::uint16_t> port_of(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(" " + key + "=");
  if (at == std::string::npos) return std::nullopt;
  const std::size_t begin = at + key.size() + 2;
  const std::string value = line.substr(begin, line.find(' ', begin) - begin);
  if (value == "off") return std::uint16_t{0};
  const std::size_t colon = value.rfind(':');
  if (colon == std::string::npos) return std::nullopt;
  const std::string digits = value.substr(colon + 1);
  if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  const int port = std::stoi(digits);
  if (port <= 0 || port > 65535) return std::nullopt;
  return static_cast<std::uint16_t>(port);
}

std::string temporary_log_path() {
  static std::atomic<int> counter{0};
  const std::string name = "ocean-server-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".log";
  return (std::filesystem::temp_directory_path() / name).string();
}

}  // namespace

std::string build_binary(const std::string& program) {
  if (!program.empty() && program.front() == '/') return program;  // a system program, as it is
  const char* build = std::getenv("OCEAN_BUILD_DIR");
  return std::string(build ? build : ".") + "/" + program;
}

std::string server_binary() { return build_binary("server/ocean-server"); }

std::optional<ListeningPorts> parse_listening_line(const std::string& log) {
  const std::size_t start = log.find("listening tcp=");
  if (start == std::string::npos) return std::nullopt;
  const std::size_t end = log.find('\n', start);
  if (end == std::string::npos) return std::nullopt;  // the line is still being written
  // From the space before "tcp=", so each key is found as " key=".
  const std::string line = log.substr(start + 9, end - start - 9);
  const auto tcp = port_of(line, "tcp"), udp = port_of(line, "udp"), metrics = port_of(line, "metrics");
  if (!tcp || !udp || !metrics || *tcp == 0) return std::nullopt;
  return ListeningPorts{*tcp, *udp, *metrics, port_of(line, "ws").value_or(0), port_of(line, "web").value_or(0)};
}

ServerProcess::ServerProcess(ServerOptions options)
    : args_(std::move(options.args)),
      log_path_(options.log_path.empty() ? temporary_log_path() : options.log_path),
      owns_log_(options.log_path.empty()) {
  args_.insert(args_.begin(), build_binary(options.program));
  if (::access(args_[0].c_str(), X_OK) != 0)
    throw std::runtime_error("no executable " + args_[0] + " (set OCEAN_BUILD_DIR to the build directory)");
  spawn();
  if (options.wait_listening && !wait_listening(options.listen_timeout_s)) {
    const std::string output = log();
    release();  // a constructor that throws gets no destructor call
    throw std::runtime_error("ocean-server did not report its ports; output:\n" + output);
  }
}

void ServerProcess::spawn() {
  std::vector<char*> argv;
  for (std::string& a : args_) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0) throw std::runtime_error("cannot write the server log " + log_path_);
  const pid_t parent = ::getpid();
  status_.reset();
  pid_ = ::fork();
  if (pid_ == 0) {
    // The child of a threaded process: async-signal-safe calls only, until execv. PDEATHSIG
    // fires when the forking thread ends, so tests start servers from their main thread.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the parent died before prctl took effect
    ::dup2(log_fd, 1);
    ::dup2(log_fd, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(log_fd);
  if (pid_ < 0) throw std::runtime_error("fork failed for " + args_[0]);
}

ServerProcess::~ServerProcess() { release(); }

void ServerProcess::release() {
  kill();
  if (owns_log_) {
    std::error_code ignored;
    std::filesystem::remove(log_path_, ignored);
  }
}

bool ServerProcess::wait_listening(double seconds) {
  const auto until = deadline_after(seconds);
  while (!listening_) {
    const bool running = alive();  // before reading, so a line written just before exit is seen
    if (const std::optional<ListeningPorts> ports = parse_listening_line(log())) {
      ports_ = *ports;
      listening_ = true;
    } else if (!running && lost_udp_port() && respawns_ < kMaxRespawns) {
      ++respawns_;
      spawn();
    } else if (!running || Clock::now() >= until) {
      return false;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  return true;
}

// The kernel picks a free TCP port and the server binds UDP on the same number, which another
// process may hold (every UDP client socket takes an ephemeral port). A fresh start gets a fresh
// TCP port; any other failure is the test's to see.
bool ServerProcess::lost_udp_port() const {
  return log().find("cannot bind UDP") != std::string::npos;
}

bool ServerProcess::wait_for_output(const std::string& needle, double seconds) {
  const auto until = deadline_after(seconds);
  for (;;) {
    const bool running = alive();  // before reading, so a last line written at exit is seen
    if (log().find(needle) != std::string::npos) return true;
    if (!running || Clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void ServerProcess::signal(int number) {
  if (!status_ && pid_ > 0) ::kill(pid_, number);
}

int ServerProcess::wait_exit(double seconds) {
  const auto until = deadline_after(seconds);
  while (!reap(false)) {
    if (Clock::now() >= until) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(*status_) ? WEXITSTATUS(*status_) : -1;
}

int ServerProcess::stop(double seconds) {
  signal(SIGTERM);
  const int status = wait_exit(seconds);
  kill();
  return status;
}

void ServerProcess::kill() {
  signal(SIGKILL);
  reap(true);
}

bool ServerProcess::alive() { return !reap(false); }

bool ServerProcess::reap(bool block) {
  if (status_ || pid_ <= 0) return true;
  int status = 0;
  pid_t reaped;
  while ((reaped = ::waitpid(pid_, &status, block ? 0 : WNOHANG)) < 0 && errno == EINTR) {
  }
  if (reaped == 0) return false;
  // Not ours to wait for (reaped elsewhere): report it as gone, not as a normal exit.
  status_ = reaped == pid_ ? status : SIGKILL;
  return true;
}

std::optional<std::uint64_t> ServerProcess::rss_kib() const {
  if (status_ || pid_ <= 0) return std::nullopt;
  std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10);
  return std::nullopt;
}

std::string ServerProcess::log() const {
  std::ifstream in(log_path_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace ocean::test_support
