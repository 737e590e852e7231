// libFuzzer harness for TcpFramer (the first reader of every TCP byte). Input: byte 0 picks the
// message size limit, bytes 1..4 the read sizes (cycled), the rest is the stream.
// Invariants: the framer agrees with a direct reading of the stream (same messages, same verdict,
// same reason), never buffers more than the limit, consumes nothing once bad, and hands out
// 8-byte aligned messages whose prefix is their own size.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"
#include "tcp_framer.hpp"

using namespace ocean::protocol;

namespace {

struct Framing {
  std::vector<std::vector<std::uint8_t>> messages;
  Reason failure = Reason::ok;  // ok: the stream ended without a bad prefix
};

// What PROTOCOL.md says the framing is: u32 LE body size, then the body.
Framing read_directly(std::span<const std::uint8_t> stream, std::size_t max_message_bytes) {
  Framing out;
  while (stream.size() >= kSizePrefixBytes) {
    const std::size_t body = std::size_t{stream[0]} | std::size_t{stream[1]} << 8 | std::size_t{stream[2]} << 16 |
                             std::size_t{stream[3]} << 24;
    if (body == 0) out.failure = Reason::empty;
    else if (body + kSizePrefixBytes > max_message_bytes) out.failure = Reason::oversized;
    else if (body + kSizePrefixBytes < kMinMessageBytes) out.failure = Reason::truncated;
    if (out.failure != Reason::ok || stream.size() < body + kSizePrefixBytes) return out;
    out.messages.emplace_back(stream.begin(), stream.begin() + kSizePrefixBytes + body);
    stream = stream.subspan(kSizePrefixBytes + body);
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ocean::fuzz::ByteReader in({data, size});
  const std::size_t limits[] = {kMinMaxMessageBytes, 4096, kDefaultMaxMessageBytes, kMaxMaxMessageBytes};
  const std::size_t max_message_bytes = limits[in.take<std::uint8_t>() % 4];
  const std::span<const std::uint8_t> cuts = in.take_bytes(4);
  const std::span<const std::uint8_t> stream = in.take_bytes(size);

  Framing seen;
  TcpFramer framer(max_message_bytes);
  std::span<const std::uint8_t> rest = stream;
  for (std::size_t i = 0; !rest.empty(); ++i) {
    const std::size_t cut = cuts.empty() ? 1 : 1 + cuts[i % cuts.size()] % 97;
    std::span<const std::uint8_t> read = rest.first(std::min(cut, rest.size()));
    rest = rest.subspan(read.size());
    while (!read.empty()) {  // a read may hold the end of one message and the start of the next
      const TcpFramer::Result r = framer.feed(read);
      FUZZ_REQUIRE(r.consumed <= read.size());
      FUZZ_REQUIRE(framer.buffered_bytes() <= max_message_bytes);
      read = read.subspan(r.consumed);
      if (r.status == TcpFramer::Status::bad) {
        FUZZ_REQUIRE(r.reason != Reason::ok);
        seen.failure = r.reason;
        const TcpFramer::Result again = framer.feed(read.empty() ? stream.first(0) : read);
        FUZZ_REQUIRE(again.status == TcpFramer::Status::bad && again.consumed == 0);
        rest = {};
        break;
      }
      if (r.status == TcpFramer::Status::need_more) {
        FUZZ_REQUIRE(read.empty());
        continue;
      }
      const std::span<const std::uint8_t> m = framer.message();
      FUZZ_REQUIRE(m.size() >= kMinMessageBytes && m.size() <= max_message_bytes);
      FUZZ_REQUIRE(reinterpret_cast<std::uintptr_t>(m.data()) % 8 == 0);
      seen.messages.emplace_back(m.begin(), m.end());
    }
  }

  const Framing expected = read_directly(stream, max_message_bytes);
  FUZZ_REQUIRE(seen.messages == expected.messages);
  FUZZ_REQUIRE(seen.failure == expected.failure);
  return 0;
}
