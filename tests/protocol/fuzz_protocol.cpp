// libFuzzer harness for every reader in ocean_protocol (built only with clang, see CMakeLists):
// verify_message under each sender/transport, decode + re-encode of whatever passes, TcpFramer
// on the input cut into reads, and ChunkAssembler on accepted chunks. Any crash or sanitizer
// report is a bug; so is an accepted message that does not survive a round trip.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "chunk_assembler.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "tcp_framer.hpp"
#include "verify_message.hpp"

using namespace ocean::protocol;
namespace wire = ocean::wire;

namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

void check_round_trip(const Verified& verified, const VerifyOptions& options) {
  const AnyMessage value = decode(*verified.message);
  const Bytes again = encode(value);
  const Verified second = verify_message(again, options);
  require(second.ok);
  require(decode(*second.message) == value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Bytes bytes(data, data + size);  // aligned copy, as a socket read into a vector is

  ChunkAssembler assembler;
  for (int i = 0; i < 4; ++i) {
    VerifyOptions options;
    options.sender = (i & 1) ? Sender::server : Sender::client;
    options.transport = (i & 2) ? wire::Transport::udp : wire::Transport::tcp;
    const Verified verified = verify_message(bytes, options);
    require(verified.ok == (verified.reason == Reason::ok));
    if (!verified.ok) continue;
    check_round_trip(verified, options);
    if (const auto* chunk = verified.message->body_as_FrameChunk()) {
      const ChunkAssembler before = assembler;
      if (assembler.add(*chunk).reason != Reason::ok) require(assembler == before);
    }
  }

  // The same bytes as a TCP stream, cut after every 7th byte.
  TcpFramer framer(4096);
  std::span<const std::uint8_t> rest(bytes);
  while (!rest.empty()) {
    const std::span<const std::uint8_t> read = rest.first(std::min<std::size_t>(7, rest.size()));
    const TcpFramer::Result r = framer.feed(read);
    require(r.consumed <= read.size());
    require(framer.buffered_bytes() <= framer.max_message_bytes());
    if (r.status == TcpFramer::Status::bad) break;
    if (r.status == TcpFramer::Status::good) (void)verify_message(framer.message(), VerifyOptions{});
    rest = rest.subspan(r.consumed == 0 ? read.size() : r.consumed);
  }
  return 0;
}
