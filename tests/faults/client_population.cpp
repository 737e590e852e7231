#include "client_population.hpp"

#include <asio/post.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>

#include "frame_verdict.hpp"

namespace ocean::faults {

std::uint64_t PopulationWindow::owed() const {
  std::uint64_t n = 0;
  for (const auto& c : clients) n += c.owed;
  return n;
}
std::uint64_t PopulationWindow::on_time() const {
  std::uint64_t n = 0;
  for (const auto& c : clients) n += c.on_time;
  return n;
}
std::uint64_t PopulationWindow::received() const {
  std::uint64_t n = 0;
  for (const auto& c : clients) n += c.received;
  return n;
}
double PopulationWindow::on_time_share() const {
  return owed() ? static_cast<double>(on_time()) / static_cast<double>(owed()) : 0.0;
}
double PopulationWindow::worst_client_share() const {
  double worst = 1.0;
  for (const auto& c : clients) worst = std::min(worst, c.on_time_share());
  return clients.empty() ? 0.0 : worst;
}
std::string PopulationWindow::describe() const {
  char line[256];
  std::snprintf(line, sizeof line, "%zu clients: owed %llu, received %llu, on time %llu = %.2f%% (worst client %.2f%%)",
                clients.size(), static_cast<unsigned long long>(owed()), static_cast<unsigned long long>(received()),
                static_cast<unsigned long long>(on_time()), 100.0 * on_time_share(), 100.0 * worst_client_share());
  return line;
}

ClientPopulation::ClientPopulation(std::uint16_t port, int udp_clients, int tcp_clients, std::uint8_t profile_id)
    : work_(asio::make_work_guard(io_)) {
  const int total = udp_clients + tcp_clients;
  tracks_.resize(static_cast<std::size_t>(total));
  for (int i = 0; i < total; ++i) {
    Track& track = tracks_[static_cast<std::size_t>(i)];
    track.udp = i < udp_clients;
    client::ClientConnectionConfig config;
    config.port = std::to_string(port);
    config.reconnect = false;  // a dropped client shows up as frames it did not get
    config.session.profile_id = profile_id;
    config.session.transport = track.udp ? wire::Transport::udp : wire::Transport::tcp;
    config.session.client_name = "faults-good-" + std::to_string(i);
    config.session.decode_memo = [this](const codec::StreamConfig& stream) { return memo_for(stream); };
    const auto index = static_cast<std::size_t>(i);
    track.connection = client::ClientConnection::create(
        io_, config, [this, index](const codec::ReconstructedFrame&, std::uint32_t tick, double arrival_s) {
          on_frame(index, tick, arrival_s);
        });
    track.connection->set_on_welcome([this, index](const protocol::Welcome& w) {
      std::lock_guard lock(mutex_);
      tracks_[index].welcome = w;
    });
  }
  thread_ = std::thread([this] { io_.run(); });
  asio::post(io_, [this] {
    for (Track& t : tracks_) t.connection->start();
  });
}

codec::DecodeMemo* ClientPopulation::memo_for(const codec::StreamConfig& config) {
  for (const auto& memo : memos_)
    if (memo->config() == config) return memo.get();
  return memos_.emplace_back(std::make_unique<codec::DecodeMemo>(config)).get();
}

ClientPopulation::~ClientPopulation() {
  asio::post(io_, [this] {
    for (Track& t : tracks_) t.connection->stop();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let the Byes go out
  work_.reset();
  io_.stop();
  thread_.join();
}

template <typename F>
auto ClientPopulation::on_io(F&& f) const {
  std::packaged_task<decltype(f())()> task(std::forward<F>(f));
  auto result = task.get_future();
  asio::post(io_, [&task] { task(); });
  return result.get();
}

void ClientPopulation::on_frame(std::size_t i, std::uint32_t tick, double arrival_s) {
  std::lock_guard lock(mutex_);
  Track& t = tracks_[i];
  if (!t.welcome) return;
  const double period = t.welcome->tick_period_s;
  const double offset = arrival_s - static_cast<double>(tick) * period;
  if (!t.fastest_offset_s || offset < *t.fastest_offset_s) t.fastest_offset_s = offset;
  const bool on_time = loadtest::arrived_on_time(arrival_s, tick, *t.fastest_offset_s, period, kInterpolationDelayS);
  t.frames.emplace(tick, on_time);  // a tick delivered twice keeps its first verdict
  const client::ClientSession* session = t.connection->session();
  if (t.udp && session && session->stats().udp.messages_in > 0) ++t.udp_frames;
}

bool ClientPopulation::wait_streaming(int frames, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    {
      std::lock_guard lock(mutex_);
      const bool ready = std::all_of(tracks_.begin(), tracks_.end(), [&](const Track& t) {
        return t.welcome && t.frames.size() >= static_cast<std::size_t>(frames) &&
               (!t.udp || t.udp_frames >= static_cast<std::uint64_t>(frames));
      });
      if (ready) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::string ClientPopulation::status() const {
  std::lock_guard lock(mutex_);
  std::string text;
  for (const Track& t : tracks_) {
    char entry[48];
    std::snprintf(entry, sizeof entry, "%s%zu/%llu ", t.welcome ? "W" : "-", t.frames.size(),
                  static_cast<unsigned long long>(t.udp_frames));
    text += entry;
  }
  return text;
}

std::uint32_t ClientPopulation::tick_now() const {
  std::lock_guard lock(mutex_);
  for (const Track& t : tracks_) {
    if (!t.welcome) continue;
    const double now_ms = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
    return static_cast<std::uint32_t>(std::floor((now_ms - static_cast<double>(t.welcome->epoch_unix_ms)) / 1000.0 /
                                                 t.welcome->tick_period_s));
  }
  return 0;
}

PopulationWindow ClientPopulation::window(std::uint32_t first, std::uint32_t last) const {
  std::lock_guard lock(mutex_);
  PopulationWindow result;
  for (const Track& t : tracks_) {
    ClientWindow w;
    std::uint32_t interval = 1;
    if (t.welcome && t.welcome->stream.rate_hz)
      interval = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(1.0 / t.welcome->tick_period_s / t.welcome->stream.rate_hz)));
    for (std::uint32_t tick = first; tick <= last; ++tick) {
      if (tick % interval) continue;
      ++w.owed;
      const auto found = t.frames.find(tick);
      if (found == t.frames.end()) continue;
      ++w.received;
      if (found->second) ++w.on_time;
    }
    result.clients.push_back(w);
  }
  return result;
}

std::optional<protocol::Welcome> ClientPopulation::welcome(std::size_t client) const {
  std::lock_guard lock(mutex_);
  return tracks_.at(client).welcome;
}

std::vector<std::uint64_t> ClientPopulation::connects() const {
  return on_io([this] {
    std::vector<std::uint64_t> n;
    for (const Track& t : tracks_) n.push_back(t.connection->counters().connects);
    return n;
  });
}

std::uint64_t ClientPopulation::keyframes(std::size_t client) const {
  return on_io([this, client]() -> std::uint64_t {
    const client::ClientSession* s = tracks_.at(client).connection->session();
    return s ? s->stats().keyframes_complete : 0;
  });
}

bool ClientPopulation::on_udp(std::size_t client) const {
  return on_io([this, client] {
    const client::ClientSession* s = tracks_.at(client).connection->session();
    return s && s->path() == client::ClientSession::Path::udp && s->stats().udp.messages_in > 0;
  });
}

std::pair<std::uint64_t, std::uint64_t> ClientPopulation::transport_changes(std::size_t client) const {
  return on_io([this, client] {
    const client::ClientSession* s = tracks_.at(client).connection->session();
    return s ? std::pair(s->stats().transport_fallbacks, s->stats().transport_returns) : std::pair<std::uint64_t, std::uint64_t>();
  });
}

}  // namespace ocean::faults
