// Runs the real ocean-server binary: exit statuses, messages, and SIGTERM handling end to end.
#include <catch2/catch.hpp>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <poll.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

std::string server_binary() {
  const char* build = std::getenv("OCEAN_BUILD_DIR");
  return std::string(build ? build : ".") + "/server/ocean-server";
}

// A child process with stdout and stderr on one pipe.
class Child {
 public:
  explicit Child(std::vector<std::string> args) {
    args.insert(args.begin(), server_binary());
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
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
    REQUIRE(spawned == 0);
  }
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    ::close(read_fd_);
  }

  // Reads output until `needle` appears or `seconds` pass; returns whether it appeared.
  bool wait_for_output(const std::string& needle, int seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (output_.find(needle) == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd p{read_fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char buffer[4096];
      const ssize_t n = ::read(read_fd_, buffer, sizeof buffer);
      if (n <= 0) return output_.find(needle) != std::string::npos;
      output_.append(buffer, static_cast<std::size_t>(n));
    }
    return true;
  }

  // After exit: the pipe's writers are gone, so read to end of file.
  void drain() {
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(read_fd_, buffer, sizeof buffer)) > 0) output_.append(buffer, static_cast<std::size_t>(n));
  }

  void signal(int number) { ::kill(pid_, number); }

  // The exit status, or -1 if it did not exit normally within `seconds`.
  int wait_exit(int seconds) {
    for (int i = 0; i < seconds * 100; ++i) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        drain();
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      ::usleep(10'000);
    }
    return -1;
  }

  const std::string& output() const { return output_; }

 private:
  pid_t pid_ = -1;
  int read_fd_ = -1;
  std::string output_;
};

const std::vector<std::string> kSmallServer = {"--listen", "127.0.0.1:0", "--metrics-listen", "off", "--size", "64",
                                               "--profiles", "lite,mobile"};

}  // namespace

TEST_CASE("ocean-server --help exits 0 and lists the options", "[process]") {
  Child child({"--help"});
  CHECK(child.wait_exit(10) == 0);
  CHECK(child.output().find("--wind-speed") != std::string::npos);
  CHECK(child.output().find("--config FILE") != std::string::npos);
}

TEST_CASE("ocean-server refuses a bad value with status 2 and a message naming it", "[process]") {
  Child child({"--wind-speed", "150"});
  CHECK(child.wait_exit(10) == 2);
  CHECK(child.output().find("--wind-speed") != std::string::npos);
  CHECK(child.output().find("[0, 100]") != std::string::npos);
}

TEST_CASE("ocean-server exits 0 on SIGTERM and on SIGINT", "[process]") {
  for (const int number : {SIGTERM, SIGINT}) {
    Child child(kSmallServer);
    REQUIRE(child.wait_for_output("listening", 20));
    child.signal(number);
    CHECK(child.wait_exit(10) == 0);
    INFO(child.output());
    CHECK(child.output().find("shutting down") != std::string::npos);
    CHECK(child.output().find("stopped") != std::string::npos);
  }
}
