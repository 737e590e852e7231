// ocean-web-replay FILE: feeds the messages a browser viewer received (the whole stream of TCP
// messages, size prefixes included, as recorded by the page) through the native ClientSession
// and prints "TICK HASH" per completed frame - hash_heights, as the page reports it - so a test
// can hold the WebAssembly decoder's output against the native one, bit for bit.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "client_session.hpp"
#include "height_hash.hpp"
#include "tcp_framer.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: ocean-web-replay FILE (the concatenated messages the page received)\n");
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "ocean-web-replay: cannot read %s\n", argv[1]);
    return 2;
  }
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  ocean::client::ClientSessionConfig config;
  config.transport = ocean::wire::Transport::tcp;
  config.close_on_bad_tcp_message = false;  // count a bad message instead of ending the replay
  ocean::client::ClientSessionEvents events;
  events.on_frame = [](const ocean::codec::ReconstructedFrame& frame, ocean::Tick tick) {
    std::printf("%lld %016" PRIx64 "\n", static_cast<long long>(tick), ocean::client::hash_heights(frame.height));
  };
  ocean::client::ClientSession session(config, events);
  session.start(0.0);
  ocean::protocol::TcpFramer framer;
  std::span<const std::uint8_t> rest(bytes);
  while (!rest.empty()) {
    const auto result = framer.feed(rest);
    rest = rest.subspan(result.consumed);
    if (result.status == ocean::protocol::TcpFramer::Status::bad) {
      std::fprintf(stderr, "ocean-web-replay: bad framing at byte %zu\n", bytes.size() - rest.size());
      return 1;
    }
    if (result.status == ocean::protocol::TcpFramer::Status::need_more) break;
    session.on_tcp_message(framer.message(), 0.0);
  }
  const auto& s = session.stats();
  std::fprintf(stderr, "ocean-web-replay: %" PRIu64 " frames, %" PRIu64 " rejected\n", s.frames_complete, s.rejected_total());
  return s.rejected_total() == 0 ? 0 : 1;
}
