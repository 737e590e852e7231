// The WebSocket transport (--ws-listen, --ws-origins) against a real Server over loopback: a
// WebSocket client reconstructs exactly what the encoder sent, like a TCP one; handshakes from
// origins outside the allow-list are refused with 403; hostile WebSocket clients (text frames,
// oversized and unmasked frames, a Ping flood that never reads) are closed with a reason while
// the other clients keep their stream; --web-listen serves the page and lets its own origin in.
#include "raw_http_get.hpp"
#include "session_harness.hpp"
#include "stream_transport.hpp"
#include "web_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>

using namespace ocean::server;
using namespace ocean::server::test;
namespace proto = ocean::protocol;

namespace {

ServerConfig websocket_config() {
  ServerConfig config = session_test_config();
  config.stream_listen["ws"] = ListenAddress{"127.0.0.1", 0};
  config.ws_origins = {"http://viewer.example:8080"};
  return config;
}

proto::Hello tcp_hello() { return proto::Hello{1, 0, ocean::wire::Transport::tcp, "ws-test"}; }

}  // namespace

TEST_CASE("a WebSocket client reconstructs exactly what the encoder sent") {
  SessionHarness harness(websocket_config());
  auto browser = harness.ws_client("http://viewer.example:8080");
  auto tool = harness.ws_client();  // no Origin: not a browser
  auto tcp = harness.client();
  CHECK(browser->ws_status == 101);
  CHECK(tool->ws_status == 101);
  std::vector<SessionTestClient*> all{browser.get(), tool.get(), tcp.get()};
  for (auto* c : all) c->hello(tcp_hello());
  REQUIRE(pump_until(all, [&] {
    for (auto* c : all)
      if (c->completed_heights.size() < 20) return false;
    return true;
  }));
  for (auto* c : all) {
    CHECK(c->errors.empty());
    CHECK(c->rejected_chunks == 0);
    harness.check_reconstructions(*c);
  }
  harness.stop();
  for (auto* c : {browser.get(), tool.get()}) {
    pump_until({c}, [&] { return !c->byes.empty(); }, std::chrono::seconds(5));
    REQUIRE(c->byes.size() == 1);  // the goodbye travels as a WebSocket message too
  }
}

TEST_CASE("WebSocket handshakes from origins outside the allow-list are refused") {
  SessionHarness harness(websocket_config());
  auto stranger = harness.ws_client("http://evil.example");
  auto lookalike = harness.ws_client("http://viewer.example:8081");
  auto allowed = harness.ws_client("http://viewer.example:8080");
  CHECK(stranger->ws_status == 403);
  CHECK(lookalike->ws_status == 403);
  CHECK(allowed->ws_status == 101);
  REQUIRE(pump_until({stranger.get(), lookalike.get()}, [&] { return stranger->closed() && lookalike->closed(); }));
  harness.stop();
  CHECK(harness.server().metrics().rejects("origin_refused").value() == 2);
}

TEST_CASE("hostile WebSocket clients are closed with a reason while the others keep their stream") {
  SessionHarness harness(websocket_config());
  auto viewer = harness.ws_client();
  auto tcp = harness.client();
  viewer->hello(tcp_hello());
  tcp->hello(tcp_hello());
  std::vector<SessionTestClient*> good{viewer.get(), tcp.get()};
  REQUIRE(pump_until(good, [&] { return viewer->completed_heights.size() >= 5 && tcp->completed_heights.size() >= 5; }));

  auto texter = harness.ws_client();
  const std::string text = "hello?";
  texter->send_raw(ocean::test::ws_client_frame(ocean::test::ws_text, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())));
  auto giant = harness.ws_client();
  std::vector<std::uint8_t> huge(proto::kDefaultMaxMessageBytes + 1024, 0x55);
  giant->send_raw(ocean::test::ws_client_frame(ocean::test::ws_binary, huge));
  auto unmasked = harness.ws_client();
  const std::uint8_t bare[] = {0x82, 0x03, 1, 2, 3};  // client frames must be masked
  unmasked->send_raw(bare);
  auto flooder = harness.ws_client();
  flooder->hello(tcp_hello());
  REQUIRE(pump_until({flooder.get()}, [&] { return flooder->welcome.has_value(); }));
  flooder->reading_paused = true;  // from now on its Pongs pile up in its bounded queue
  std::vector<std::uint8_t> pings;
  for (int i = 0; i < 4000; ++i) {
    proto::Ping ping;
    ping.session_id = flooder->welcome->session_id;
    ping.seq = static_cast<std::uint32_t>(i);
    const auto frame = ocean::test::ws_client_frame(ocean::test::ws_binary, proto::encode(ping));
    pings.insert(pings.end(), frame.begin(), frame.end());
  }
  flooder->send_raw(pings);

  // A client that closes with 1009 itself: its own word, not a verdict on its input.
  auto leaver = harness.ws_client();
  const std::uint8_t going[] = {0x03, 0xf1};  // 1009
  leaver->send_raw(ocean::test::ws_client_frame(ocean::test::ws_close, going));
  // WebSocket Pings from a client that reads nothing: the server's Pongs are bounded like its queue.
  auto pinger = harness.ws_client();
  pinger->reading_paused = true;
  {
    const std::vector<std::uint8_t> payload(125, 0x21);
    const auto ping = ocean::test::ws_client_frame(ocean::test::ws_ping, payload);
    std::vector<std::uint8_t> burst;
    for (int i = 0; i < 1000; ++i) burst.insert(burst.end(), ping.begin(), ping.end());
    for (int i = 0; i < 100 && !pinger->send_failed(); ++i) pinger->send_raw(burst);  // 13 MB of Pongs owed
  }
  pinger->reading_paused = false;
  // Half an upgrade request, then gone: the connection must not outlive it (ASan's leak check).
  {
    asio::io_context context;
    asio::ip::tcp::socket half(context);
    half.connect({asio::ip::make_address("127.0.0.1"), harness.server().ws_port().value()});
    const std::string start = "GET /ocean HTTP/1.1\r\nHost: 127.0.0.1\r\n";
    asio::write(half, asio::buffer(start));
  }

  std::vector<SessionTestClient*> hostile{texter.get(), giant.get(), unmasked.get(), leaver.get(), pinger.get()};
  std::vector<SessionTestClient*> everyone = good;
  everyone.insert(everyone.end(), hostile.begin(), hostile.end());
  const std::size_t viewer_before = viewer->completed_heights.size(), tcp_before = tcp->completed_heights.size();
  REQUIRE(pump_until(everyone, [&] {
    for (auto* c : hostile)
      if (!c->closed()) return false;
    return viewer->completed_heights.size() >= viewer_before + 30 && tcp->completed_heights.size() >= tcp_before + 30;
  }));
  CHECK(texter->ws_close_code == 1003);   // unsupported data
  CHECK(giant->ws_close_code == 1009);    // message too big
  CHECK(unmasked->ws_close_code == 1002); // protocol error
  CHECK(leaver->ws_close_code == 1009);   // its own code, echoed
  for (auto* c : good) {
    CHECK(c->errors.empty());
    CHECK(c->byes.empty());
    harness.check_reconstructions(*c);
  }
  harness.stop();
  ServerMetrics& metrics = harness.server().metrics();
  CHECK(metrics.rejects("oversized").value() == 1);  // the giant; the leaver's 1009 was its own
  CHECK(metrics.rejects("unexpected_message").value() >= 2);  // the text and the unmasked frame
}

TEST_CASE("the page server (--web-listen) serves the page, names the WebSocket port, and lets its origin in") {
  const auto root = std::filesystem::temp_directory_path() / ("ocean-web-root-" + std::to_string(::getpid()));
  std::filesystem::create_directories(root);
  for (const std::string& name : WebFiles::names()) std::ofstream(root / name) << "<!-- " << name << " -->";
  ServerConfig config = websocket_config();
  config.web_listen = ListenAddress{"127.0.0.1", 0};
  config.web_root = root.string();
  SessionHarness harness(config);
  REQUIRE(harness.server().web_port());
  const std::uint16_t web = *harness.server().web_port();
  const std::string page = raw_http_get(web, "/?connect=1");
  CHECK(page.rfind("HTTP/1.1 200", 0) == 0);
  CHECK(page.find("<!-- index.html -->") != std::string::npos);
  CHECK(raw_http_get(web, "/ocean-web.json").find("{\"ws_port\": " + std::to_string(*harness.server().ws_port()) + ", ") !=
        std::string::npos);
  CHECK(raw_http_get(web, "/../server.cpp").rfind("HTTP/1.1 404", 0) == 0);
  // The page's origin as the browser names it (the host it reached the WebSocket by, the page's
  // port) needs no --ws-origins entry; the same host's other ports and other names do not pass.
  auto own = harness.ws_client("http://127.0.0.1:" + std::to_string(web));
  auto other_port = harness.ws_client("http://127.0.0.1:" + std::to_string(web == 65535 ? web - 1 : web + 1));
  auto other_name = harness.ws_client("http://localhost:" + std::to_string(web));
  CHECK(own->ws_status == 101);
  CHECK(other_port->ws_status == 403);
  CHECK(other_name->ws_status == 403);
  // One host holds at most an eighth of the page listener's connections: idle ones included.
  {
    asio::io_context context;
    std::vector<asio::ip::tcp::socket> idle;
    for (std::size_t i = 0; i < WebFiles::kMaxConnections / 8; ++i) {
      idle.emplace_back(context);
      idle.back().connect({asio::ip::make_address("127.0.0.1"), web});
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // accepted before the next
    CHECK(raw_http_get(web, "/").empty());  // closed at once
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the idle ones' closes are seen
  CHECK(raw_http_get(web, "/").rfind("HTTP/1.1 200", 0) == 0);
  harness.stop();
  CHECK(harness.server().metrics().rejects("http_busy").value() == 1);
  std::filesystem::remove_all(root);
}

TEST_CASE("the ws gauge counts WebSocket viewers and returns to 0 when the last one leaves") {
  SessionHarness harness(websocket_config());
  Gauge& ws = harness.server().metrics().clients("mobile", "ws");
  auto viewer = harness.ws_client("http://viewer.example:8080");
  viewer->hello(tcp_hello());
  REQUIRE(pump_until({viewer.get()}, [&] { return viewer->completed_heights.size() >= 5; }));
  CHECK(ws.value() == 1.0);
  viewer.reset();  // the browser tab closes
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (ws.value() != 0.0 && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(ws.value() == 0.0);  // main: stayed 1 (update_client_gauges seeded only tcp and udp)
  harness.stop();
}

TEST_CASE("every stream transport opens links that carry its name, and the primary one is always on") {
  // The gauges and logs label a session by its link's transport(), and the server seeds each
  // transport's gauge from the table: the two must agree, or a gauge never returns to 0.
  asio::io_context context;
  asio::ip::tcp::acceptor acceptor(context, asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  ServerConfig config;
  REQUIRE(listen_address(stream_transports().front(), config) == &config.listen);
  for (const StreamTransport& transport : stream_transports()) {
    asio::ip::tcp::socket client(context);
    client.connect(acceptor.local_endpoint());
    asio::ip::tcp::socket accepted = acceptor.accept();
    const TransportContext transport_context{config, 1 << 16, 0, nullptr, {}};
    const std::shared_ptr<StreamLink> link = transport.open(std::move(accepted), transport_context);
    REQUIRE(link);
    CHECK(link->transport() == transport.name);
    // One row per name: the gauges and logs tell transports apart by it.
    CHECK(std::count_if(stream_transports().begin(), stream_transports().end(),
                        [&](const StreamTransport& t) { return t.name == transport.name; }) == 1);
    link->close("test_done");
  }
  const auto row = [](std::string_view name) -> const StreamTransport* {
    for (const StreamTransport& t : stream_transports())
      if (t.name == name) return &t;
    return nullptr;
  };
  CHECK(row("carrier-pigeon") == nullptr);
  // A transport the config leaves off has no address: no listener, no gauge.
  REQUIRE(row("ws") != nullptr);
  CHECK(listen_address(*row("ws"), config) == nullptr);
  config.stream_listen["ws"] = ListenAddress{"127.0.0.1", 0};
  CHECK(listen_address(*row("ws"), config) == &config.stream_listen.at("ws"));
}
