// make_corpus OUT_DIR: writes the fuzzers' seed corpora from real traffic - a FakeServer <->
// ClientSession exchange (its messages, and the frame record blocks of its FrameData messages and
// frames datagrams), every message type built by the protocol's encoders, a real codec stream, a
// minted cookie, metrics requests and the shipped config - one folder per harness
// (OUT_DIR/<harness>/seed_NNN). Generated at build time; never committed.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "client_exchange.hpp"
#include "codec_stream.hpp"
#include "frame_records.hpp"
#include "message_builders.hpp"
#include "record_format.hpp"
#include "udp_cookie.hpp"

using namespace ocean;
namespace fs = std::filesystem;
using Seed = std::vector<std::uint8_t>;

namespace {

class CorpusWriter {
 public:
  CorpusWriter(fs::path dir) : dir_(std::move(dir)) { fs::create_directories(dir_); }
  void add(std::span<const std::uint8_t> bytes) {
    char name[32];
    std::snprintf(name, sizeof name, "seed_%03d", next_++);
    std::ofstream(dir_ / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                       static_cast<std::streamsize>(bytes.size()));
  }
  void add(std::string_view text) { add({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}); }
  int count() const { return next_; }

 private:
  fs::path dir_;
  int next_ = 0;
};

std::vector<protocol::Bytes> client_messages() {
  const protocol::Bytes cookie{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  protocol::ParamChange change;
  change.admin_token = "secret";
  change.request_id = 7;
  change.wind_speed_mps = 14.0;
  change.spectrum = wire::Spectrum::jonswap;
  return {protocol::encode(protocol::Hello{1, 2'000'000, wire::Transport::udp, "fuzz-seed"}),
          protocol::encode(protocol::UdpHello{42, cookie}),
          protocol::encode(protocol::Ack{42, cookie, 100, 0xFFFF0F0Fu}),
          protocol::encode(protocol::KeyframeRequest{42, cookie, wire::KeyframeReason::lost_baseline}),
          protocol::encode(protocol::SetTransport{wire::Transport::tcp}),
          protocol::encode(change),
          protocol::encode(protocol::Ping{42, cookie, 3, 123456}),
          protocol::encode(protocol::Bye{wire::ByeReason::client_quit, "bye"}),
          protocol::encode(protocol::Error{protocol::Reason::out_of_range, "wind_speed out of range"}),
          protocol::encode(protocol::SceneUpdate{5, 900, protocol::SceneParams{}, 2})};
}

// The frame record block a server message carries, if any: a FrameData's frames, or a frames
// datagram after its kind byte. Empty for anything else.
std::span<const std::uint8_t> block_of(const fuzz::ServerMessage& m) {
  if (m.transport == wire::Transport::udp) {
    if (!m.bytes.empty() && m.bytes[0] == static_cast<std::uint8_t>(protocol::DatagramKind::frames))
      return std::span(m.bytes).subspan(1);
    return {};
  }
  const auto* data = wire::GetSizePrefixedMessage(m.bytes.data())->body_as_FrameData();
  if (!data || !data->frames()) return {};
  return {data->frames()->data(), data->frames()->size()};
}

// The message a server datagram or TCP message holds, if any (a message datagram after its kind byte).
std::span<const std::uint8_t> message_of(const fuzz::ServerMessage& m) {
  if (m.transport == wire::Transport::tcp) return m.bytes;
  if (!m.bytes.empty() && m.bytes[0] == static_cast<std::uint8_t>(protocol::DatagramKind::message))
    return std::span(m.bytes).subspan(1);
  return {};
}

// Blocks encode_frame_block() makes that the exchange may not hold: a multi-chunk key, deltas at
// the lag limit, ticks past 2^32 and at the top of the range, the most records a block holds.
std::vector<protocol::Bytes> synthetic_blocks() {
  const protocol::Bytes payload(40, 0x5A);
  const std::span<const std::uint8_t> p(payload);
  using protocol::FrameRecord;
  const Tick top = ~Tick{0};
  std::vector<protocol::Bytes> out;
  out.push_back(protocol::encode_frame_block(std::vector<FrameRecord>{
      FrameRecord{10, 10, true, 0, 3, p}, FrameRecord{10, 10, true, 1, 3, p}, FrameRecord{10, 10, true, 2, 3, p}}));
  out.push_back(protocol::encode_frame_block(std::vector<FrameRecord>{
      FrameRecord{5000, 5000 - protocol::kMaxFrameLag, false, 0, 1, p}, FrameRecord{5001, 5000, false, 0, 1, p}}));
  out.push_back(protocol::encode_frame_block(std::vector<FrameRecord>{
      FrameRecord{0xFFFF'FFFFull, 0xFFFF'FFF0ull, false, 0, 2, p}, FrameRecord{0x1'0000'0000ull, 0xFFFF'FFFFull, false, 1, 2, p}}));
  out.push_back(protocol::encode_frame_block(std::vector<FrameRecord>{
      FrameRecord{top, top, true, protocol::kMaxChunksPerFrame - 1, protocol::kMaxChunksPerFrame, p}}));
  std::vector<FrameRecord> full;
  for (Tick t = 0; t < protocol::kMaxRecordsPerBlock; ++t)
    full.push_back(FrameRecord{900 + t, 900 + t - t % 3, t % 3 == 0, 0, 1, p.first(t % 5)});
  out.push_back(protocol::encode_frame_block(full));
  return out;
}

void write_protocol_seeds(const fs::path& out) {
  const std::vector<fuzz::ServerMessage> exchange = fuzz::record_client_exchange(8);
  CorpusWriter verify(out / "fuzz_verify_message"), framer(out / "fuzz_tcp_framer"),
      session(out / "fuzz_client_session"), blocks(out / "fuzz_frame_block");
  std::vector<protocol::Bytes> all = client_messages();
  for (const auto& m : exchange)
    if (const auto message = message_of(m); !message.empty()) all.emplace_back(message.begin(), message.end());

  // Every block of the exchange, and one of its first records together, oldest first, as the
  // server's UDP redundancy sends them (a frames datagram for the client, a FrameData for verify).
  std::vector<protocol::FrameRecord> copies;
  for (const auto& m : exchange) {
    const auto block = block_of(m);
    if (block.empty()) continue;
    blocks.add(block);
    std::vector<protocol::FrameRecord> records;
    if (protocol::decode_frame_block(block, records))
      for (const protocol::FrameRecord& r : records)
        if (copies.size() < 3) copies.push_back(r);  // payloads view `exchange`, alive here
  }
  protocol::Bytes redundant;
  if (!copies.empty()) {
    redundant = protocol::frames_datagram(copies);
    blocks.add(std::span(redundant).subspan(1));
    all.push_back(protocol::encode(protocol::FrameData{protocol::Bytes(redundant.begin() + 1, redundant.end())}));
  }
  for (const protocol::Bytes& block : synthetic_blocks()) {
    blocks.add(block);
    all.push_back(protocol::encode(protocol::FrameData{block}));
  }
  for (const auto& m : all) verify.add(m);

  // Framer: limit selector 2 (64 KiB), read sizes, then a stream of real messages.
  for (std::size_t start = 0; start < all.size(); start += 4) {
    Seed seed{2, 7, 64, 1, 200};
    for (std::size_t i = start; i < std::min(all.size(), start + 4); ++i) seed.insert(seed.end(), all[i].begin(), all[i].end());
    framer.add(seed);
  }

  // Client session: everything the server sent after the Welcome, in order, 50 ms apart; and
  // each message alone.
  for (std::uint8_t mode : {0, 1}) {
    Seed seed{mode};
    for (std::size_t i = 1; i < exchange.size(); ++i) {
      const bool udp = exchange[i].transport == wire::Transport::udp;
      fuzz::append_record(seed, static_cast<std::uint8_t>((udp ? 1 : 0) | 2 | 16), exchange[i].bytes);
    }
    session.add(seed);
  }
  if (!redundant.empty()) {
    Seed seed{1};  // the harness replays the Welcome itself
    fuzz::append_record(seed, 1, redundant);
    session.add(seed);
  }
  for (std::size_t i = 1; i < exchange.size(); ++i) {
    Seed seed{1};
    fuzz::append_record(seed, exchange[i].transport == wire::Transport::udp ? 1 : 0, exchange[i].bytes);
    session.add(seed);
  }
}

void write_codec_seeds(const fs::path& out) {
  const auto frames = fuzz::make_codec_stream(6);
  CorpusWriter codec(out / "fuzz_codec_decoder");
  for (std::uint8_t fix_crc : {0, 1}) {
    Seed fresh{0};  // a fresh decoder: the key's chunks
    for (const codec::Chunk& c : frames[0]->chunks) fuzz::append_record(fresh, fix_crc, fuzz::chunk_record(c));
    codec.add(fresh);
    for (std::size_t f = 3; f < frames.size(); ++f) {  // a primed decoder (ticks 1..3): later deltas
      Seed primed{1};
      for (const codec::Chunk& c : frames[f]->chunks) fuzz::append_record(primed, fix_crc, fuzz::chunk_record(c));
      codec.add(primed);
    }
  }
  for (const codec::Chunk& c : frames[3]->chunks) {  // single chunks
    Seed one{1};
    fuzz::append_record(one, 1, fuzz::chunk_record(c));
    codec.add(one);
  }
}

void write_server_seeds(const fs::path& out) {
  CorpusWriter cookie(out / "fuzz_udp_cookie"), http(out / "fuzz_http_request"), config(out / "fuzz_config_toml");
  server::CookieKey key{};
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<std::uint8_t>(0xA5 ^ i);  // fuzz_udp_cookie's key
  const asio::ip::udp::endpoint sender(asio::ip::make_address_v4("192.0.2.7"), 40000);
  const std::int64_t now = 1'767'225'600'000;
  for (std::int64_t at : {now, now + 40'000}) {  // valid, then expired
    Seed seed;
    for (int i = 0; i < 8; ++i) seed.push_back(static_cast<std::uint8_t>(at >> (8 * i)));
    const server::Cookie c = server::mint_cookie(key, 42, sender, now);
    seed.insert(seed.end(), c.begin(), c.end());
    cookie.add(seed);
  }

  for (std::string_view request :
       {"\x07GET /metrics HTTP/1.1\r\nHost: localhost:9464\r\nUser-Agent: Prometheus/2.45\r\nAccept: text/plain\r\n\r\n",
        "\x01GET /healthz?probe=1 HTTP/1.0\r\n\r\n", "\x20HEAD /readyz HTTP/1.1\r\nConnection: close\r\n\r\n",
        "\x03POST /metrics HTTP/1.1\r\nContent-Length: 0\r\n\r\n"})
    http.add(request);

  config.add(
      "listen = \"0.0.0.0:7700\"\nmetrics-listen = \"127.0.0.1:9464\"\nsize = 256\npatch = 256.0\n"
      "spectrum = \"jonswap\"\nspreading = \"donelan-banner\"\nwind-speed = 12.0\nwind-dir = 0.0\n"
      "fetch = 100000.0\namplitude = 1.0\ndepth = \"deep\"\nchoppiness = 0.0\nsmall-wave = 0.0\nseed = 1\n"
      "tick-rate = 30\nepoch = 2026-01-01T00:00:00Z\nprofiles = [\"mobile\", \"desktop\"]\nmax-clients = 64\n"
      "idle-timeout = 10.0\nlog-level = \"info\"\n");
  config.add(
      "size = 128\nwind-speed = 8.0\n\n[[schedule]]\ntick = 300\nwind-speed = 20.0\nspectrum = \"phillips\"\n\n"
      "[[schedule]]\ntick = 900\nwind-dir = 45.0\ndepth = 30.0\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR  (writes OUT_DIR/<harness>/seed_NNN)\n", argv[0]);
    return 2;
  }
  const fs::path out = argv[1];
  write_protocol_seeds(out);
  write_codec_seeds(out);
  write_server_seeds(out);
  std::printf("make_corpus: seeds written under %s\n", out.c_str());
  return 0;
}
