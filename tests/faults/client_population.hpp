// ClientPopulation: well-behaved ClientConnections (UDP and TCP) on one io_context thread, each
// frame judged on time as the load test judges it (frame_verdict's arrived_on_time against the
// client's fastest arrival so far, plus the interpolation delay), so a test can ask what share of
// the frames a window of ticks owed each client arrived in time. Its clients share their decoding
// as the load test's do (a DecodeMemo per stream): on one thread, 13 clients each building a new
// scene's model at its first frame held the last one's frames 100 ms and more, which a fault test
// took for the server's lateness.
#pragma once

#include <asio/executor_work_guard.hpp>
#include <asio/io_context.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "client_connection.hpp"
#include "decode_memo.hpp"
#include "message_types.hpp"

namespace ocean::faults {

inline constexpr double kInterpolationDelayS = 0.1;  // three 30 Hz send intervals (FrameTimeline default)

struct ClientWindow {
  std::uint64_t owed = 0;      // frame ticks of the stream in the window
  std::uint64_t received = 0;  // of those, frames delivered
  std::uint64_t on_time = 0;   // of those, delivered by their render time
  double on_time_share() const { return owed ? static_cast<double>(on_time) / static_cast<double>(owed) : 0.0; }
};

struct PopulationWindow {
  std::vector<ClientWindow> clients;
  std::uint64_t owed() const;
  std::uint64_t on_time() const;
  std::uint64_t received() const;
  double on_time_share() const;     // over all clients
  double worst_client_share() const;
  std::string describe() const;     // one line for the test log
};

class ClientPopulation {
 public:
  // profile_id: the profile every client asks for (mobile = 1).
  ClientPopulation(std::uint16_t port, int udp_clients, int tcp_clients, std::uint8_t profile_id);
  ~ClientPopulation();
  ClientPopulation(const ClientPopulation&) = delete;
  ClientPopulation& operator=(const ClientPopulation&) = delete;

  std::size_t size() const { return tracks_.size(); }
  // True once every client has a Welcome, and every UDP client has had `frames` frames over UDP.
  bool wait_streaming(int frames, double timeout_s);
  // The server tick at this moment of the system clock (from the Welcome's epoch and period).
  std::uint32_t tick_now() const;
  // Per client: welcomed, frames, frames while on UDP (for a failed wait's message).
  std::string status() const;
  // Frames owed and judged for the ticks [first, last].
  PopulationWindow window(std::uint32_t first, std::uint32_t last) const;
  std::optional<protocol::Welcome> welcome(std::size_t client) const;
  // Sessions started per client (TCP connects); 1 each when nobody was dropped.
  std::vector<std::uint64_t> connects() const;
  // Frames the client's sessions completed as keyframes, and whether its deltas come on UDP now.
  std::uint64_t keyframes(std::size_t client) const;
  bool on_udp(std::size_t client) const;
  // Its session's fallbacks to TCP and returns to UDP so far.
  std::pair<std::uint64_t, std::uint64_t> transport_changes(std::size_t client) const;

 private:
  struct Track {
    std::shared_ptr<client::ClientConnection> connection;
    bool udp = false;
    std::optional<protocol::Welcome> welcome;
    std::optional<double> fastest_offset_s;  // min over arrivals of arrival - tick * period
    std::map<std::uint32_t, bool> frames;     // tick -> on time
    std::uint64_t udp_frames = 0;
  };
  void on_frame(std::size_t i, std::uint32_t tick, double arrival_s);
  template <typename F>
  auto on_io(F&& f) const;  // runs f on the io thread and waits for its result

  codec::DecodeMemo* memo_for(const codec::StreamConfig& config);  // on the io thread only
  std::vector<std::unique_ptr<codec::DecodeMemo>> memos_;
  mutable asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_;
  std::vector<Track> tracks_;
  mutable std::mutex mutex_;
  std::thread thread_;
};

}  // namespace ocean::faults
