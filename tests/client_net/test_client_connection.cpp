// ClientConnection over loopback against TinyServer, a minimal in-test TCP acceptor that answers a
// Hello with a Welcome (TCP only) and a keyframe plus a few deltas; reconnection after it restarts;
// a PacketLink delaying the TCP downlink.
#include <catch2/catch.hpp>

#include <asio/read.hpp>
#include <asio/write.hpp>
#include <chrono>
#include <optional>
#include <queue>

#include "client_connection.hpp"
#include "fake_server.hpp"

using namespace ocean;
using namespace ocean::client;
using namespace ocean::client::test;

namespace {

class TinyServer {
 public:
  // with_udp: the Welcome offers a UDP port; a proven client gets kFrames more deltas by UDP.
  TinyServer(asio::io_context& io, std::uint16_t port, std::uint32_t first_tick, bool with_udp = false)
      : acceptor_(io, asio::ip::tcp::endpoint(asio::ip::address_v4::loopback(), port)),
        socket_(io),
        udp_(io),
        first_tick_(first_tick),
        encoder_(FakeServer().config()),
        truth_(64, 64.0) {
    encoder_.set_scene(0, 0, codec::scene_model_params(FakeServer().welcome().scene));
    if (with_udp) {
      udp_.open(asio::ip::udp::v4());
      udp_.bind(asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
      do_udp_read();
    }
    acceptor_.async_accept([this](std::error_code ec, asio::ip::tcp::socket s) {
      if (!ec) {
        socket_ = std::move(s);
        do_read();
      }
    });
  }

  std::uint16_t port() const { return acceptor_.local_endpoint().port(); }
  void close() {
    std::error_code ec;
    socket_.close(ec);
    acceptor_.close(ec);
    udp_.close(ec);
  }
  const codec::EncodedFrame* frame(std::uint32_t tick) const {
    auto it = frames_.find(tick);
    return it == frames_.end() ? nullptr : it->second.get();
  }

  int hellos = 0, byes = 0, udp_hellos = 0, udp_acks = 0;
  static constexpr std::uint32_t kFrames = 5;

 private:
  void do_read() {
    socket_.async_read_some(asio::buffer(buffer_), [this](std::error_code ec, std::size_t n) {
      if (ec) return;
      std::span<const std::uint8_t> rest(buffer_.data(), n);
      while (!rest.empty()) {
        const auto r = framer_.feed(rest);
        rest = rest.subspan(r.consumed);
        if (r.status != protocol::TcpFramer::Status::good) break;
        const auto v = protocol::verify_message(framer_.message(), {protocol::Sender::client, wire::Transport::tcp});
        if (!v) continue;
        if (v.message->body_type() == wire::Body::Hello) ++hellos, answer_hello();
        if (v.message->body_type() == wire::Body::Bye) ++byes;
        if (v.message->body_type() == wire::Body::Ack) on_ack(v.message->body_as_Ack()->latest_tick64());
      }
      do_read();
    });
  }

  protocol::Welcome welcome() const {
    FakeServerOptions options;
    options.offer_udp = udp_.is_open();
    protocol::Welcome welcome = FakeServer(options).welcome();
    welcome.current_tick = first_tick_;
    if (udp_.is_open()) welcome.udp_port = udp_.local_endpoint().port();
    return welcome;
  }

  // The frames of ticks [from, to), each a delta from the one before (a key at first_tick_).
  std::vector<protocol::Bytes> frames(Tick from, Tick to, bool udp) {
    std::vector<protocol::Bytes> out;
    for (Tick t = from - 1; t < to; ++t) {
      truth_.at(t, 1.0 / 30.0);
      encoder_.add_truth(t, truth_.view());
      if (t < from) continue;
      auto f = t == first_tick_ ? encoder_.encode_key(t) : encoder_.encode_delta(t, previous_);
      previous_ = f->id;
      frames_[t] = f;
      for (const codec::Chunk& c : f->chunks) {
        const protocol::FrameRecord record{c.tick, c.baseline, c.key, c.index, c.count, c.payload};
        const std::span<const protocol::FrameRecord> one(&record, 1);
        out.push_back(udp ? protocol::frames_datagram(one)
                          : protocol::encode(protocol::FrameData{protocol::encode_frame_block(one)}));
      }
    }
    return out;
  }

  void answer_hello() {
    out_ = protocol::encode(welcome());
    for (const auto& bytes : frames(first_tick_, first_tick_ + kFrames, false)) out_.insert(out_.end(), bytes.begin(), bytes.end());
    asio::async_write(socket_, asio::buffer(out_), [](std::error_code, std::size_t) {});
  }

  // Deltas go by UDP only once the address is proven and the client holds their baseline (acked).
  void on_ack(Tick latest_tick) {
    if (!udp_peer_ || udp_sent_ || latest_tick != first_tick_ + kFrames - 1) return;
    udp_sent_ = true;
    udp_out_ = frames(first_tick_ + kFrames, first_tick_ + 2 * kFrames, true);
    for (const auto& b : udp_out_) udp_.send_to(asio::buffer(b), *udp_peer_);
  }

  void do_udp_read() {
    udp_.async_receive_from(asio::buffer(udp_in_), udp_from_, [this](std::error_code ec, std::size_t n) {
      if (ec) return;
      const protocol::Bytes datagram(udp_in_.begin(), udp_in_.begin() + n);
      const auto v = protocol::verify_message(datagram, {protocol::Sender::client, wire::Transport::udp});
      const auto w = welcome();
      if (v && protocol::check_udp_sender(*v.message, w.session_id, w.udp_cookie) == protocol::Reason::ok) {
        if (v.message->body_type() == wire::Body::Ack) {
          ++udp_acks;
          on_ack(v.message->body_as_Ack()->latest_tick64());
        }
        if (v.message->body_type() == wire::Body::UdpHello) {
          ++udp_hellos;
          udp_peer_ = udp_from_;
          udp_.send_to(asio::buffer(protocol::message_datagram(protocol::encode(protocol::UdpReady{w.session_id}))),
                       *udp_peer_);
        }
      }
      do_udp_read();
    });
  }

  asio::ip::tcp::acceptor acceptor_;
  asio::ip::tcp::socket socket_;
  asio::ip::udp::socket udp_;
  asio::ip::udp::endpoint udp_from_;
  std::optional<asio::ip::udp::endpoint> udp_peer_;
  bool udp_sent_ = false;
  std::array<std::uint8_t, 2048> udp_in_{};
  std::vector<protocol::Bytes> udp_out_;
  codec::StateId previous_;
  std::uint32_t first_tick_;
  codec::Encoder encoder_;
  WaveTruth truth_;
  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 4096> buffer_{};
  protocol::Bytes out_;
  std::map<std::uint32_t, std::shared_ptr<const codec::EncodedFrame>> frames_;
};

template <typename Done>
bool run_until(asio::io_context& io, Done done, double seconds = 5.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done() && std::chrono::steady_clock::now() < until) io.run_for(std::chrono::milliseconds(5));
  return done();
}

struct Received {
  std::uint32_t tick;
  double arrival;
  bool exact;
};

// A fixed-delay link: the simplest PacketLink a load test could plug in.
struct DelayLink {
  double delay_s;
  std::queue<std::pair<double, std::vector<std::uint8_t>>> q;
  void send(std::vector<std::uint8_t> b, double now) { q.emplace(now + delay_s, std::move(b)); }
  template <typename F>
  void deliver(double now, F&& f) {
    while (!q.empty() && q.front().first <= now) {
      auto b = std::move(q.front().second);
      q.pop();
      f(std::move(b));
    }
  }
  double next_due() const { return q.empty() ? -1.0 : q.front().first; }
};

}  // namespace

TEST_CASE("connection: loopback handshake and frames, then reconnect after the server restarts", "[connection]") {
  asio::io_context io;
  auto server = std::make_unique<TinyServer>(io, 0, 10);
  const std::uint16_t port = server->port();
  std::vector<Received> got;
  ClientConnectionConfig config;
  config.port = std::to_string(port);
  config.reconnect_min_s = 0.05;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double at) {
    const codec::EncodedFrame* sent = server->frame(tick);
    got.push_back({tick, at, sent && sent->reconstruction.height == f.height && sent->reconstruction.slope_x == f.slope_x});
  });
  int session_ends = 0;
  connection->set_on_session_end([&](const ClientSession& s, const std::string&) {
    ++session_ends;
    CHECK(s.stats().frames_complete == TinyServer::kFrames);
  });
  connection->start();
  REQUIRE(run_until(io, [&] { return got.size() == TinyServer::kFrames; }));
  for (std::uint32_t i = 0; i < TinyServer::kFrames; ++i) {
    CHECK(got[i].tick == 10 + i);
    CHECK(got[i].exact);
  }
  CHECK(server->hellos == 1);
  CHECK(connection->session()->path() == ClientSession::Path::tcp);  // Welcome offered no UDP
  CHECK(connection->counters().connects == 1);

  // The server goes away; the client notices, retries, and comes back when it returns.
  server->close();
  REQUIRE(run_until(io, [&] { return !connection->connected(); }));
  io.run_for(std::chrono::milliseconds(200));  // a failed attempt or two
  server.reset();
  server = std::make_unique<TinyServer>(io, port, 500);
  REQUIRE(run_until(io, [&] { return got.size() == 2 * TinyServer::kFrames; }));
  for (std::uint32_t i = 0; i < TinyServer::kFrames; ++i) {
    CHECK(got[TinyServer::kFrames + i].tick == 500 + i);
    CHECK(got[TinyServer::kFrames + i].exact);
  }
  CHECK(server->hellos == 1);
  CHECK(connection->counters().connects == 2);
  CHECK(connection->counters().disconnects == 1);
  CHECK(connection->counters().connect_attempts >= 3);
  CHECK(session_ends == 1);
  CHECK(connection->session()->stats().keyframes_complete == 1);  // a new session starts from a key

  connection->stop();
  REQUIRE(run_until(io, [&] { return server->byes == 1; }, 2.0));
}

TEST_CASE("connection: a PacketLink on the TCP downlink delays every message", "[connection]") {
  asio::io_context io;
  TinyServer server(io, 0, 1);
  ConnectionLinks links;
  links.tcp_down = std::make_unique<PacketLinkAdapter<DelayLink>>(DelayLink{0.15, {}});
  ClientConnectionConfig config;
  config.port = std::to_string(server.port());
  std::vector<double> arrivals;
  auto connection = ClientConnection::create(
      io, config, [&](const codec::ReconstructedFrame&, std::uint32_t, double at) { arrivals.push_back(at); },
      std::move(links));
  const double started = ClientConnection::now_s();
  connection->start();
  REQUIRE(run_until(io, [&] { return arrivals.size() == TinyServer::kFrames; }));
  CHECK(arrivals.front() - started >= 0.15);
  CHECK(arrivals.front() - started < 1.0);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("connection: the UDP socket from the Welcome proves itself and carries deltas", "[connection]") {
  asio::io_context io;
  TinyServer server(io, 0, 1, true);
  ClientConnectionConfig config;
  config.port = std::to_string(server.port());
  std::vector<Received> got;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double at) {
    const codec::EncodedFrame* sent = server.frame(tick);
    got.push_back({tick, at, sent && sent->reconstruction.height == f.height});
  });
  connection->start();
  REQUIRE(run_until(io, [&] { return got.size() == 2 * TinyServer::kFrames && server.udp_acks > 0; }));
  for (std::uint32_t i = 0; i < got.size(); ++i) {
    CHECK(got[i].tick == 1 + i);
    CHECK(got[i].exact);
  }
  const ClientSession& session = *connection->session();
  CHECK(session.path() == ClientSession::Path::udp);
  CHECK(server.udp_hellos >= 1);
  CHECK(session.stats().udp.messages_in >= 1 + TinyServer::kFrames);  // UdpReady + the deltas
  CHECK(session.stats().udp.bytes_out >= protocol::kUdpHelloMinBytes);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}
