// The real ocean-server under misbehaving peers while 10 UDP and 3 TCP well-behaved clients
// stream the mobile profile: each fault must leave them >= 99% of their owed frames on time, the
// server alive, healthy and within a stated memory bound. Figures are printed ("[faults]" lines).
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <mutex>
#include <random>
#include <thread>

#include "fault_scenario.hpp"
#include "message_builders.hpp"
#include "ocean_generated.h"
#include "protocol_version.hpp"
#include "raw_peers.hpp"
#include "verify_message.hpp"
#include "websocket_test_frames.hpp"

using namespace ocean::faults;
namespace proto = ocean::protocol;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

constexpr std::uint64_t kSendQueueKib = 1024;  // SessionCoreOptions::send_queue_bytes, per session

// Under ASan (OCEAN_SANITIZE) freed memory sits in a quarantine, so resident memory says nothing
// about what the server holds: the memory bounds are then printed, not asserted. The server of
// this build tree is built like this test.
#if defined(OCEAN_SANITIZED)
constexpr bool kMemoryMeasurable = false;
#else
constexpr bool kMemoryMeasurable = true;
#endif

void check_memory_bound(const FaultMeasure& m, std::uint64_t bound_kib) {
  INFO("server RSS grew " << m.rss_growth_kib() << " KiB; bound " << bound_kib << " KiB");
  if (kMemoryMeasurable) CHECK(m.rss_growth_kib() <= bound_kib);
}

std::vector<std::string> small_server(int max_clients, double idle_timeout_s) {
  return {"--size", "64", "--profiles", "mobile,lite", "--max-clients", std::to_string(max_clients), "--idle-timeout",
          std::to_string(idle_timeout_s)};
}

double rejects(const std::string& metrics, const std::string& reason) {
  return metric_value(metrics, "ocean_rejects_total{reason=\"" + reason + "\"}").value_or(0.0);
}

// A UdpHello without its padding (encode() always pads): answering it would amplify.
proto::Bytes unpadded_udp_hello(std::uint64_t session_id, const proto::Bytes& cookie) {
  flatbuffers::FlatBufferBuilder fbb;
  const auto body = ocean::wire::CreateUdpHello(fbb, session_id, fbb.CreateVector(cookie));
  fbb.FinishSizePrefixed(ocean::wire::CreateMessage(fbb, ocean::protocol::kProtocolVersion, ocean::wire::Body::UdpHello, body.Union()),
                         ocean::protocol::kFileIdentifier);
  return proto::Bytes(fbb.GetBufferPointer(), fbb.GetBufferPointer() + fbb.GetSize());
}

proto::Hello hello(std::uint8_t profile, ocean::wire::Transport transport, const std::string& name) {
  return proto::Hello{profile, 0, transport, name};
}

// After a WebSocket upgrade and a Hello: the Welcome's session id (0 if none came within 3 s).
std::uint64_t ws_welcome_session(RawTcp& c) {
  std::vector<std::uint8_t> head;
  ocean::test::WsDeframer deframer;
  bool upgraded = false;
  const auto end = Clock::now() + milliseconds(3000);
  while (Clock::now() < end) {
    const std::vector<std::uint8_t> bytes = c.read_raw(0.1);
    if (!upgraded) {
      head.insert(head.end(), bytes.begin(), bytes.end());
      const std::string text(head.begin(), head.end());
      const std::size_t blank = text.find("\r\n\r\n");
      if (blank == std::string::npos) continue;
      upgraded = true;
      deframer.feed(std::span(head).subspan(blank + 4));
    } else {
      deframer.feed(bytes);
    }
    while (auto frame = deframer.next()) {
      std::vector<std::uint64_t> aligned((frame->payload.size() + 7) / 8);
      std::memcpy(aligned.data(), frame->payload.data(), frame->payload.size());
      const auto verified = proto::verify_message(std::span(reinterpret_cast<const std::uint8_t*>(aligned.data()), frame->payload.size()),
                                                  {proto::Sender::server, ocean::wire::Transport::tcp});
      if (verified && verified.message->body_type() == ocean::wire::Body::Welcome)
        return verified.message->body_as_Welcome()->session_id();
    }
  }
  return 0;
}

}  // namespace

TEST_CASE("clients that stop reading cost the server at most their bounded send queues", "[faults]") {
  FaultScenario s(small_server(64, 3.0));
  start_population(s);
  constexpr int kStalled = 6;
  const std::string metrics_before = s.metrics();
  const double drops_before = metric_value(metrics_before, "ocean_send_queue_drops_total").value_or(-1);
  const double keys_before = metric_value(metrics_before, "ocean_keyframes_sent_total").value_or(-1);
  std::vector<RawTcp> stalled;
  std::vector<std::uint64_t> ids;
  for (int i = 0; i < kStalled; ++i) {
    RawTcp c(s.port(), 4096);  // a small receive window: the server's writes back up at once
    const auto welcome = c.handshake(hello(kMobile, ocean::wire::Transport::tcp, "stalled-reader"));
    REQUIRE(welcome);
    stalled.push_back(std::move(c));
    ids.push_back(welcome->session_id);
  }
  std::atomic<bool> stop{false};
  std::thread keepalive;
  const FaultMeasure m = s.measure("6 readers that stop", [&] {
    // They never read again, but keep the session alive (idle timeout 3 s) and send a
    // SetTransport{tcp} every frame, each of which owes them a re-sync keyframe (the largest frame).
    keepalive = std::thread([&] {
      lower_thread_priority();
      const proto::Bytes to_tcp = proto::encode(proto::SetTransport{ocean::wire::Transport::tcp});
      for (std::uint32_t round = 0; !stop; ++round) {
        for (std::size_t i = 0; i < stalled.size(); ++i) {
          stalled[i].send(to_tcp);
          if (round % 15 == 0) stalled[i].send(proto::encode(proto::Ping{ids[i], {}, round, 0}));
        }
        std::this_thread::sleep_for(milliseconds(33));
      }
    });
    std::this_thread::sleep_for(milliseconds(4000));
  });
  const std::string metrics = s.metrics();
  stop = true;
  keepalive.join();
  check_population(s, m);
  const double drops = metric_value(metrics, "ocean_send_queue_drops_total").value_or(-1) - drops_before;
  const double keys = metric_value(metrics, "ocean_keyframes_sent_total").value_or(-1) - keys_before;
  // Printed: how much of the growth came in the second half (queues filling towards their bound).
  const std::size_t half = m.rss_samples_kib.size() / 2;
  const std::uint64_t mid = m.rss_samples_kib.empty() ? 0 : m.rss_samples_kib[half];
  const std::uint64_t late_growth = m.rss_peak_kib > mid ? m.rss_peak_kib - mid : 0;
  std::printf("[faults] stalled readers: %.0f keyframes queued, %.0f frames dropped at the queue bound, RSS growth in the "
              "second half %llu KiB\n", keys, drops, static_cast<unsigned long long>(late_growth));
  // Frames are small and keys rate-limited, so in 4 s the queues stay under their 1 MiB bound
  // (drops are printed, not asserted); what is asserted is that the memory they cost stays within
  // their bound: their queues plus 8 MiB (allocator slack, the encodings they share).
  CHECK(keys > kStalled);  // they were offered frames they did not read
  check_memory_bound(m, kStalled * kSendQueueKib + 8 * 1024);
}

TEST_CASE("a client that stops reading but keeps sending Pings cannot grow the server's memory", "[faults]") {
  FaultScenario s(small_server(64, 3.0));
  start_population(s);
  constexpr int kFlooders = 2;
  // Bound: the two sessions' send queues plus 16 MiB of slack.
  constexpr std::uint64_t kBoundKib = kFlooders * kSendQueueKib + 16 * 1024;
  const std::uint64_t rss_start = s.server().rss_kib().value_or(0);
  std::atomic<std::uint64_t> pings{0};
  const FaultMeasure m = s.measure("2 non-readers flood Pings", [&] {
    std::vector<std::thread> threads;
    for (int t = 0; t < kFlooders; ++t)
      threads.emplace_back([&] {
        lower_thread_priority();
        RawTcp c(s.port(), 4096);
        const auto welcome = c.handshake(hello(kMobile, ocean::wire::Transport::tcp, "ping-flood"));
        if (!welcome) return;
        // Each Pong it does not read is queued for it; 64 Pings (of its own session) per write.
        proto::Bytes batch;
        for (int i = 0; i < 64; ++i) {
          const proto::Bytes ping = proto::encode(proto::Ping{welcome->session_id, {}, static_cast<std::uint32_t>(i), 0});
          batch.insert(batch.end(), ping.begin(), ping.end());
        }
        // Stops early once the server grew 4x past the bound: enough to fail, and the machine is spared.
        const auto end = Clock::now() + milliseconds(3000);
        for (std::uint64_t n = 0; Clock::now() < end && c.send(batch); ++n) {
          pings += 64;
          if (n % 256 == 0 && s.server().rss_kib().value_or(0) > rss_start + 4 * kBoundKib) break;
        }
        std::this_thread::sleep_until(end);  // the others are measured over the whole 3 s
      });
    for (auto& t : threads) t.join();
  });
  check_population(s, m);
  std::printf("[faults] ping flood: %llu Pings sent by readers that never read\n",
              static_cast<unsigned long long>(pings.load()));
  CHECK(pings > 10000);  // the flood happened
  // Pongs fill the bounded queue; then the server closes such a session instead of queueing more.
  const std::string metrics = s.metrics();
  CHECK(rejects(metrics, "send_queue_full") >= kFlooders);
  CHECK(metric_value(metrics, "ocean_send_queue_max_bytes").value_or(1e12) <= (kSendQueueKib + 64) * 1024.0);
  check_memory_bound(m, kBoundKib);
}

TEST_CASE("half messages and stalls are timed out while other clients stream", "[faults]") {
  constexpr double kIdle = 3.0, kHandshake = 3.0;  // --idle-timeout; --handshake-timeout (default)
  FaultScenario s(small_server(64, kIdle));
  start_population(s);
  struct Outcome {
    std::string kind;
    RawTcp::Ending ending;
    double closed_after_s = 0.0;
  };
  std::vector<Outcome> outcomes;
  std::mutex mutex;
  const FaultMeasure m = s.measure("half messages and stalls", [&] {
    std::vector<std::thread> threads;
    auto attacker = [&](std::string kind, std::function<void(RawTcp&)> act) {
      threads.emplace_back([&, kind, act] {
        lower_thread_priority();
        RawTcp c(s.port());
        const auto start = Clock::now();
        act(c);
        Outcome o{kind, c.wait_closed(kHandshake + 3.0 - std::chrono::duration<double>(Clock::now() - start).count()), 0.0};
        o.closed_after_s = std::chrono::duration<double>(Clock::now() - start).count();
        std::lock_guard lock(mutex);
        outcomes.push_back(o);
      });
    };
    const proto::Bytes hello_bytes = proto::encode(hello(kMobile, ocean::wire::Transport::tcp, "half"));
    for (int i = 0; i < 4; ++i) {
      attacker("prefix only", [&](RawTcp& c) { c.send(std::span(hello_bytes).first(2)); });
      attacker("half a Hello", [&](RawTcp& c) { c.send(std::span(hello_bytes).first(hello_bytes.size() / 2)); });
      attacker("welcomed, then half a Ping", [&](RawTcp& c) {
        if (!c.handshake(hello(kMobile, ocean::wire::Transport::tcp, "half-ping"))) return;
        const proto::Bytes ping = proto::encode(proto::Ping{1, {}, 1, 0});
        c.send(std::span(ping).first(ping.size() / 2));
      });
    }
    for (int i = 0; i < 2; ++i)
      attacker("Hello one byte per 400 ms", [&](RawTcp& c) {
        // 12 bytes in 4.8 s: never a whole Hello within the handshake time.
        for (std::size_t b = 0; b < 12; ++b) {
          c.send(std::span(hello_bytes).subspan(b, 1));
          std::this_thread::sleep_for(milliseconds(400));
        }
      });
    for (auto& t : threads) t.join();
  });
  check_population(s, m);
  REQUIRE(outcomes.size() == 14);
  for (const Outcome& o : outcomes) {
    INFO(o.kind << ": closed " << o.ending.closed << " after " << o.closed_after_s << " s");
    std::printf("[faults] %-28s closed=%d after %.2f s  error=%s bye=%d\n", o.kind.c_str(), o.ending.closed,
                o.closed_after_s, o.ending.error ? std::string(proto::to_string(o.ending.error->code)).c_str() : "-",
                o.ending.bye ? static_cast<int>(o.ending.bye->reason) : -1);
    CHECK(o.ending.closed);
    if (o.kind == "welcomed, then half a Ping") {
      REQUIRE(o.ending.bye);
      CHECK(o.ending.bye->reason == ocean::wire::ByeReason::idle_timeout);
      CHECK(o.closed_after_s >= kIdle - 0.1);
      CHECK(o.closed_after_s <= kIdle + 2.5);
    } else {
      REQUIRE(o.ending.error);
      CHECK(o.ending.error->code == proto::Reason::timeout);
      CHECK(o.closed_after_s >= kHandshake - 0.1);
      CHECK(o.closed_after_s <= kHandshake + 2.5);
    }
  }
}

TEST_CASE("clients that vanish or reconnect in a tight loop leave no session behind", "[faults]") {
  // Room for the population and 12 more: a session or a handshake left behind would soon make
  // the server refuse newcomers with server_full.
  const int max_clients = kUdpClients + kTcpClients + 12;
  FaultScenario s(small_server(max_clients, 3.0));
  start_population(s);
  std::atomic<int> vanished{0};
  const FaultMeasure gone = s.measure("connect and vanish", [&] {
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t)
      threads.emplace_back([&, t] {
        lower_thread_priority();
        const proto::Bytes hello_bytes = proto::encode(hello(kMobile, ocean::wire::Transport::udp, "vanish"));
        for (int i = 0; i < 120; ++i) {
          RawTcp c(s.port());
          switch ((i + t) % 6) {
            case 0: c.close(); break;                 // connect, FIN
            case 1: c.close_with_reset(); break;      // connect, RST
            case 2: c.send(hello_bytes); c.close(); break;           // Hello, FIN before the Welcome
            case 3: c.send(std::span(hello_bytes).first(7)); c.close_with_reset(); break;  // half a Hello, RST
            case 4: if (c.handshake(hello(kMobile, ocean::wire::Transport::udp, "vanish"))) c.close_with_reset(); break;
            case 5:  // welcomed and streaming, then FIN with no Bye
              if (c.handshake(hello(kMobile, ocean::wire::Transport::tcp, "vanish"))) c.read_message(0.2);
              c.close();
              break;
          }
          ++vanished;
        }
      });
    for (auto& t : threads) t.join();
  });
  check_population(s, gone);
  std::atomic<int> welcomes{0}, refused{0}, attempts{0};
  const FaultMeasure loop = s.measure("reconnect in a tight loop", [&] {
    std::vector<std::thread> threads;
    for (int t = 0; t < 1; ++t)  // one client gone wrong: thousands of sessions a second
      threads.emplace_back([&] {
        lower_thread_priority();
        const auto end = Clock::now() + milliseconds(3000);
        while (Clock::now() < end) {
          RawTcp c(s.port());
          ++attempts;
          if (c.handshake(hello(kMobile, ocean::wire::Transport::udp, "reconnect-loop"), 1.0)) ++welcomes;
          else ++refused;
        }
      });
    for (auto& t : threads) t.join();
  });
  check_population(s, loop);
  std::printf("[faults] churn: %d connections vanished; reconnect loop %d attempts (%.0f/s), %d welcomed, %d refused\n",
              vanished.load(), attempts.load(), attempts / loop.seconds, welcomes.load(), refused.load());
  CHECK(welcomes > 100);
  // Every vanished and looping session is gone: the gauges count the population only, and a
  // newcomer is welcomed.
  double clients = -1;
  for (int i = 0; i < 40 && clients != s.population().size(); ++i) {
    std::this_thread::sleep_for(milliseconds(100));
    clients = metric_sum(s.metrics(), "ocean_clients");
  }
  CHECK(clients == static_cast<double>(s.population().size()));
  RawTcp newcomer(s.port());
  CHECK(newcomer.handshake(hello(kMobile, ocean::wire::Transport::udp, "newcomer")));
  check_memory_bound(gone, 16 * 1024);
  check_memory_bound(loop, 16 * 1024);
}

TEST_CASE("UDP garbage and forged datagrams are dropped unanswered while the victim streams", "[faults]") {
  FaultScenario s(small_server(64, 3.0));
  start_population(s);
  const auto victim = s.population().welcome(0);
  REQUIRE(victim);
  REQUIRE(victim->udp_port == s.port());
  REQUIRE(s.population().on_udp(0));
  settle_key_roots();
  const std::uint64_t victim_keys_before = s.population().keyframes(0);
  const std::string before = s.metrics();
  std::atomic<std::uint64_t> datagrams{0};
  std::atomic<std::uint64_t> bytes_out{0}, bytes_in{0};
  std::atomic<int> tcp_pongs{0}, tcp_errors{0};
  bool tcp_attacker_open = false;
  const FaultMeasure m = s.measure("UDP flood, forged ids", [&] {
    std::vector<std::thread> threads;
    for (const char* ip : {"127.0.0.1", "127.0.0.2"})
      threads.emplace_back([&, ip] {
        lower_thread_priority();
        RawUdp udp(ip);
        std::mt19937 random(std::string(ip) == "127.0.0.1" ? 1 : 2);
        proto::Bytes wrong_cookie = victim->udp_cookie;
        wrong_cookie[5] ^= 0x40;
        const std::uint32_t tick = s.population().tick_now();
        const std::vector<proto::Bytes> forged = {
            proto::encode(proto::Ack{victim->session_id, wrong_cookie, tick, ~0u}),
            proto::encode(proto::Ack{victim->session_id, victim->udp_cookie, tick, ~0u}),  // real cookie, unproven port
            proto::encode(proto::Ping{victim->session_id, wrong_cookie, 7, 7}),
            proto::encode(proto::Ping{victim->session_id, victim->udp_cookie, 7, 7}),
            proto::encode(proto::KeyframeRequest{victim->session_id, victim->udp_cookie, ocean::wire::KeyframeReason::decode_error}),
            proto::encode(proto::UdpHello{victim->session_id, wrong_cookie}),
            proto::encode(proto::UdpHello{victim->session_id ^ 1, victim->udp_cookie}),
            proto::encode(proto::Ack{victim->session_id ^ 0xffff, victim->udp_cookie, tick, 0}),
        };
        // The victim's own UdpHello, replayed from another IP: its cookie is bound to 127.0.0.1.
        const proto::Bytes replayed_hello = proto::encode(proto::UdpHello{victim->session_id, victim->udp_cookie});
        const proto::Bytes unpadded = unpadded_udp_hello(victim->session_id, victim->udp_cookie);
        const proto::Bytes ping = proto::encode(proto::Ping{victim->session_id, victim->udp_cookie, 1, 1});
        const auto end = Clock::now() + milliseconds(3000);
        std::uint64_t n = 0;
        while (Clock::now() < end) {
          // 40 datagrams per 10 ms: 4000 per second per socket.
          for (int burst = 0; burst < 40; ++burst, ++n) {
            proto::Bytes d;
            switch (n % 8) {
              case 0: d.resize(1 + random() % 1200); for (auto& b : d) b = static_cast<std::uint8_t>(random()); break;
              case 1: d.assign(1201 + random() % 3000, 0x4f); break;  // oversized
              case 2: d = forged[random() % forged.size()]; d.resize(d.size() - 1 - random() % (d.size() - 1)); break;  // truncated
              case 3: d = forged[random() % forged.size()]; d[12 + random() % (d.size() - 12)] ^= 0xff; break;  // corrupted
              case 4: case 5: d = forged[random() % forged.size()]; break;
              case 6: d = std::string(ip) == "127.0.0.2" ? replayed_hello : forged[0]; break;
              case 7:
                if (n % 16 == 7) {
                  d = unpadded;  // the victim's real cookie, but too short to be answered
                } else {
                  d = ping;
                  d[0] = static_cast<std::uint8_t>(random());  // a wrong size prefix
                }
                break;
            }
            udp.send_to(s.port(), d);
          }
          udp.drain();
          std::this_thread::sleep_for(milliseconds(10));
        }
        std::this_thread::sleep_for(milliseconds(200));
        udp.drain();
        datagrams += udp.datagrams_out();
        bytes_out += udp.bytes_out();
        bytes_in += udp.bytes_in();
      });
    // Meanwhile a TCP session sends Acks, KeyframeRequests and Pings carrying the victim's id.
    // (It reads what it is sent, so its own frames do not count as answers: only Pongs would.)
    threads.emplace_back([&] {
      lower_thread_priority();
      RawTcp c(s.port());
      if (!c.handshake(hello(kMobile, ocean::wire::Transport::tcp, "foreign-ids"))) return;
      const auto end = Clock::now() + milliseconds(3000);
      std::uint32_t seq = 0;
      while (Clock::now() < end) {
        const std::uint32_t tick = s.population().tick_now();
        c.send(proto::encode(proto::Ack{victim->session_id, victim->udp_cookie, tick, ~0u}));
        c.send(proto::encode(proto::KeyframeRequest{victim->session_id, victim->udp_cookie, ocean::wire::KeyframeReason::lost_baseline}));
        c.send(proto::encode(proto::Ping{victim->session_id, victim->udp_cookie, ++seq, 0}));
        const auto until = Clock::now() + milliseconds(50);
        while (Clock::now() < until) {
          const auto message = c.read_message(0.01);
          if (!message) continue;
          if (std::holds_alternative<proto::Pong>(*message)) ++tcp_pongs;
          if (std::holds_alternative<proto::Error>(*message)) ++tcp_errors;
        }
      }
      tcp_attacker_open = c.connected();
    });
    for (auto& t : threads) t.join();
  });
  check_population(s, m);
  const std::string after = s.metrics();
  double dropped = 0;
  for (const char* reason : {"truncated", "oversized", "empty", "trailing_bytes", "bad_identifier", "bad_verifier",
                             "unknown_version", "unknown_message_type", "unexpected_message", "missing_field",
                             "bad_cookie", "bad_session", "unpadded_udp_hello", "bad_enum", "out_of_range", "bad_string"})
    dropped += rejects(after, reason) - rejects(before, reason);
  std::printf("[faults] UDP flood: %llu datagrams (%.0f/s, %llu bytes) sent, %llu bytes came back, %.0f counted as rejects\n",
              static_cast<unsigned long long>(datagrams.load()), static_cast<double>(datagrams.load()) / m.seconds,
              static_cast<unsigned long long>(bytes_out.load()),
              static_cast<unsigned long long>(bytes_in.load()), dropped);
  std::printf("[faults] TCP messages with the victim's id: %d Pongs and %d Errors came back, connection %s\n",
              tcp_pongs.load(), tcp_errors.load(), tcp_attacker_open ? "kept" : "closed");
  CHECK(datagrams > 6000);  // over 2000 per second even on a loaded machine (about 8000 when idle)
  CHECK(bytes_in <= bytes_out);  // no amplification...
  CHECK(bytes_in == 0);          // ...and nothing of it was answered at all
  CHECK(dropped >= 0.5 * static_cast<double>(datagrams));  // read and refused (the rest lost in the kernel buffer)
  for (const char* reason : {"oversized", "truncated", "bad_cookie", "bad_session", "bad_verifier", "unpadded_udp_hello"})
    CHECK(rejects(after, reason) > rejects(before, reason));
  // A TCP session's messages naming another session are dropped (counted as bad_session), not
  // answered, and do not end the sender's session.
  CHECK(tcp_pongs == 0);
  CHECK(tcp_errors == 0);
  CHECK(tcp_attacker_open);
  // The victim stayed on UDP at its address, and nothing sent with its id asked it for a key.
  CHECK(s.population().on_udp(0));
  const ClientWindow& victim_window = m.window.clients.at(0);
  // A victim that itself missed frames on a starved machine asks for a key of its own (CI's
  // sanitizer run once kept 22 % of frames on time before any fault): then a key proves nothing.
  const std::uint64_t victim_keys = s.population().keyframes(0) - victim_keys_before;
  if (machine_kept_up(m) || victim_window.on_time == victim_window.owed)
    CHECK(victim_keys == 0);
  else
    std::printf("[faults] NOT ASSERTED: the victim got %llu keys while it kept %.2f%% of its frames on time\n",
                static_cast<unsigned long long>(victim_keys), 100.0 * victim_window.on_time_share());
  if (machine_kept_up(m)) CHECK(victim_window.on_time_share() >= kOnTimeShare);
}

TEST_CASE("WebSocket clients that send garbage, flood or never read leave the others on time", "[faults]") {
  std::vector<std::string> args = small_server(64, 3.0);
  args.insert(args.end(), {"--ws-listen", "127.0.0.1:0"});
  FaultScenario s(args);
  REQUIRE(s.server().ws_port() != 0);
  start_population(s);
  const std::uint16_t ws = s.server().ws_port();
  const auto text = [](const std::string& t) { return std::span(reinterpret_cast<const std::uint8_t*>(t.data()), t.size()); };
  std::atomic<int> bad_connections{0};
  std::atomic<std::uint64_t> pings{0};
  const FaultMeasure m = s.measure("WebSocket garbage and a non-reader's Ping flood", [&] {
    std::vector<std::thread> threads;
    // Connection after connection, each with one kind of bad input after a good handshake.
    threads.emplace_back([&] {
      lower_thread_priority();
      const std::vector<std::uint8_t> huge(proto::kDefaultMaxMessageBytes + 4096, 0x5a);
      const std::vector<std::vector<std::uint8_t>> bad = {
          ocean::test::ws_client_frame(ocean::test::ws_text, text("{\"hello\": 1}")),
          ocean::test::ws_client_frame(ocean::test::ws_binary, huge),
          {0x82, 0x05, 1, 2, 3, 4, 5},  // unmasked
          ocean::test::ws_client_frame(ocean::test::ws_binary, text("not a protocol message at all")),
          {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff}};
      const auto end = Clock::now() + milliseconds(3000);
      for (std::size_t i = 0; Clock::now() < end; ++i) {
        RawTcp c(ws);
        const std::string upgrade = ocean::test::ws_upgrade_request(ws);
        if (!c.send(text(upgrade)) || !c.send(bad[i % bad.size()])) continue;
        ++bad_connections;
        std::this_thread::sleep_for(milliseconds(20));
      }
    });
    // A WebSocket viewer that stops reading and floods Pings: its Pongs fill its bounded queue.
    threads.emplace_back([&] {
      lower_thread_priority();
      RawTcp c(ws, 4096);
      const std::string upgrade = ocean::test::ws_upgrade_request(ws);
      if (!c.send(text(upgrade))) return;
      const auto hello_frame = ocean::test::ws_client_frame(ocean::test::ws_binary, proto::encode(hello(kMobile, ocean::wire::Transport::tcp, "ws-flood")));
      if (!c.send(hello_frame)) return;
      const std::uint64_t session = ws_welcome_session(c);
      if (session == 0) return;
      std::vector<std::uint8_t> batch;
      for (int i = 0; i < 64; ++i) {
        const auto frame = ocean::test::ws_client_frame(ocean::test::ws_binary, proto::encode(proto::Ping{session, {}, static_cast<std::uint32_t>(i), 0}));
        batch.insert(batch.end(), frame.begin(), frame.end());
      }
      const auto end = Clock::now() + milliseconds(3000);
      while (Clock::now() < end && c.send(batch)) pings += 64;
      std::this_thread::sleep_until(end);
    });
    for (auto& t : threads) t.join();
  });
  check_population(s, m);
  std::printf("[faults] websocket: %d bad connections, %llu Pings from a reader that never read\n", bad_connections.load(),
              static_cast<unsigned long long>(pings.load()));
  CHECK(bad_connections > 20);
  CHECK(pings > 1000);
  const std::string metrics = s.metrics();
  CHECK(rejects(metrics, "oversized") >= 1);
  CHECK(rejects(metrics, "unexpected_message") >= 2);  // text and unmasked frames
  CHECK(rejects(metrics, "send_queue_full") + rejects(metrics, "idle_timeout") >= 1);  // the flooder is gone
  CHECK(s.healthy());
}
