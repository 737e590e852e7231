// libFuzzer harness for verify_message (the gate every received message passes), under each
// sender x transport, and decode() of what it accepts. Input: one whole message, size prefix
// included (a TcpFramer message or a datagram). Supersedes tests/protocol/fuzz_protocol.cpp.
// Invariants: ok <=> reason ok; an accepted message may be sent by that sender over that
// transport, fits the transport's size limit, decodes, re-encodes, re-verifies and decodes to the
// same value; a UDP-accepted client message's sender check never crashes; a chunk the assembler
// refuses changes nothing.
#include <cstdint>

#include "chunk_assembler.hpp"
#include "fuzz_check.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "verify_message.hpp"

using namespace ocean::protocol;
namespace wire = ocean::wire;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Bytes bytes(data, data + size);  // aligned, as a socket read into a vector is
  const std::uint8_t cookie[kMinCookieBytes] = {1, 2, 3, 4, 5, 6, 7, 8};

  for (int i = 0; i < 4; ++i) {
    VerifyOptions options;
    options.sender = (i & 1) ? Sender::server : Sender::client;
    options.transport = (i & 2) ? wire::Transport::udp : wire::Transport::tcp;
    const Verified verified = verify_message(bytes, options);
    FUZZ_REQUIRE(verified.ok == (verified.reason == Reason::ok));
    FUZZ_REQUIRE(verified.ok == (verified.message != nullptr));
    if (!verified.ok) {
      FUZZ_REQUIRE(!describe(verified).empty());
      continue;
    }
    const wire::Body type = verified.message->body_type();
    FUZZ_REQUIRE(may_send(options.sender, type));
    FUZZ_REQUIRE(may_travel(options.transport, type));
    FUZZ_REQUIRE(bytes.size() <= (options.transport == wire::Transport::udp ? kMaxDatagram : options.max_message_bytes));

    const AnyMessage value = decode(*verified.message);
    const Bytes again = encode(value);
    const Verified second = verify_message(again, options);
    FUZZ_REQUIRE(second.ok);
    FUZZ_REQUIRE(decode(*second.message) == value);

    if (options.sender == Sender::client && options.transport == wire::Transport::udp)
      (void)check_udp_sender(*verified.message, 42, cookie);
    if (const auto* chunk = verified.message->body_as_FrameChunk()) {
      ChunkAssembler assembler;
      const ChunkAssembler before = assembler;
      const ChunkAssembler::Outcome outcome = assembler.add(*chunk);
      if (outcome.reason != Reason::ok) FUZZ_REQUIRE(assembler == before);
    }
  }
  return 0;
}
