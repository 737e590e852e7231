// ServerProcess: the one way tests start the real ocean-server of the build tree.
//
// Ports: give the server port 0 (--listen 127.0.0.1:0, or listen = "127.0.0.1:0" in a config)
// and read the ports it bound from its "listening tcp=... udp=... metrics=..." line (ports()).
// The kernel picks the port as the server binds it, so no other process can take it between a
// probe and the bind, and parallel CTest jobs never collide. The server binds UDP on the number
// TCP got; when that one is taken, wait_listening() starts it again (a new TCP port).
//
// Output: stdout and stderr go to a log file, never a pipe: a pipe nobody reads fills up and
// stalls the server mid-test (a reconnect storm logs a line per connection).
//
// Lifetime: the child gets SIGKILL when the test process dies (PR_SET_PDEATHSIG), so a crashed
// or aborted test leaves no server behind; the destructor SIGKILLs one still running.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace ocean::test_support {

// $OCEAN_BUILD_DIR/server/ocean-server; CTest sets OCEAN_BUILD_DIR (ocean_add_test), "." otherwise.
std::string server_binary();
// $OCEAN_BUILD_DIR/`program`; an absolute `program` as it is (a store a test runs beside).
std::string build_binary(const std::string& program);

// The ports of the first "listening" line in `log`; 0 for one that is "off".
struct ListeningPorts {
  std::uint16_t tcp = 0;
  std::uint16_t udp = 0;
  std::uint16_t metrics = 0;
  std::uint16_t ws = 0;   // --ws-listen
  std::uint16_t web = 0;  // --web-listen
};
std::optional<ListeningPorts> parse_listening_line(const std::string& log);

struct ServerOptions {
  // The program, relative to the build tree; another of the project's tools (the load test
  // beside a server) runs the same way, with wait_listening off.
  std::string program = "server/ocean-server";
  std::vector<std::string> args;  // after the binary's name
  std::string log_path;           // empty: a temporary file, removed with the ServerProcess
  // Whether the constructor waits for the "listening" line and throws (with the log) without
  // it. Off for a server expected to exit (--help, a bad flag) or to start several at once.
  bool wait_listening = true;
  double listen_timeout_s = 20.0;
};

class ServerProcess {
 public:
  // Throws std::runtime_error when the binary is missing or (wait_listening) it does not listen.
  explicit ServerProcess(ServerOptions options);
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  // Waits for the "listening" line; false when the server exited or said nothing of the sort
  // within `seconds` (log() then tells why). True at once when it was already seen.
  bool wait_listening(double seconds);
  // Waits until `needle` appears in the log; false after `seconds` or when the server exited
  // without writing it.
  bool wait_for_output(const std::string& needle, double seconds);

  const ListeningPorts& ports() const { return ports_; }  // zeros before wait_listening()
  std::uint16_t tcp_port() const { return ports_.tcp; }
  std::uint16_t metrics_port() const { return ports_.metrics; }
  std::uint16_t ws_port() const { return ports_.ws; }
  std::uint16_t web_port() const { return ports_.web; }

  void signal(int number);
  // The exit status, or -1 when it did not exit normally (a signal) or not within `seconds`.
  int wait_exit(double seconds);
  // SIGTERM, the way an operator stops it; SIGKILL after `seconds`. The exit status, as wait_exit.
  int stop(double seconds = 10.0);
  // SIGKILL: no Bye, no FIN from the application; the kernel closes its sockets.
  void kill();

  bool alive();
  pid_t pid() const { return pid_; }
  // VmRSS in KiB; nullopt when the process is gone.
  std::optional<std::uint64_t> rss_kib() const;
  std::string log() const;  // everything it wrote to stdout and stderr so far

 private:
  void spawn();
  void release();  // kills the server and removes a temporary log
  bool reap(bool block);  // true when it has exited (status_ set)
  bool lost_udp_port() const;

  static constexpr int kMaxRespawns = 5;
  std::vector<std::string> args_;  // the binary first
  std::string log_path_;
  bool owns_log_ = false;
  pid_t pid_ = -1;
  std::optional<int> status_;  // waitpid's status once reaped
  ListeningPorts ports_;
  bool listening_ = false;
  int respawns_ = 0;
};

}  // namespace ocean::test_support
