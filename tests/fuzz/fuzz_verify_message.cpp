// libFuzzer harness for verify_message (the gate every received message passes), under each
// sender x transport, and decode() of what it accepts. Input: one whole message, size prefix
// included (a TcpFramer message, or a datagram's message after its kind byte). Supersedes
// tests/protocol/fuzz_protocol.cpp.
// Invariants: ok <=> reason ok; an accepted message may be sent by that sender over that
// transport, is never a version-1 FrameChunk or FrameBundle, fits the transport's size limit,
// decodes, re-encodes, re-verifies and decodes to the same value; a UDP-accepted client message's
// sender check never crashes; an accepted FrameData's block either decodes to records that
// re-encode to the same records or is refused with nothing taken (fuzz_frame_block goes deeper).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "frame_records.hpp"
#include "fuzz_check.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "verify_message.hpp"

using namespace ocean::protocol;
namespace wire = ocean::wire;

namespace {

bool same_records(const std::vector<FrameRecord>& a, const std::vector<FrameRecord>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].tick != b[i].tick || a[i].baseline != b[i].baseline || a[i].key != b[i].key || a[i].index != b[i].index ||
        a[i].count != b[i].count || a[i].payload.size() != b[i].payload.size() ||
        !std::equal(a[i].payload.begin(), a[i].payload.end(), b[i].payload.begin()))
      return false;
  return true;
}

void check_frame_data(const wire::FrameData& data) {
  const auto* frames = data.frames();
  FUZZ_REQUIRE(frames != nullptr && frames->size() > 0);  // the field check's rule
  std::vector<FrameRecord> records;
  const FrameBlockResult parsed = decode_frame_block({frames->data(), frames->size()}, records);
  if (!parsed) {
    FUZZ_REQUIRE(records.empty());
    FUZZ_REQUIRE(!parsed.rule.empty());
    return;
  }
  FUZZ_REQUIRE(!records.empty());
  const Bytes again = encode_frame_block(records);
  std::vector<FrameRecord> second;
  FUZZ_REQUIRE(decode_frame_block(again, second));
  FUZZ_REQUIRE(same_records(records, second));
}

}  // namespace

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
    FUZZ_REQUIRE(type != wire::Body::FrameChunk && type != wire::Body::FrameBundle);  // version 1 only
    FUZZ_REQUIRE(bytes.size() <= (options.transport == wire::Transport::udp ? kMaxDatagram : options.max_message_bytes));

    const AnyMessage value = decode(*verified.message);
    const Bytes again = encode(value);
    const Verified second = verify_message(again, options);
    FUZZ_REQUIRE(second.ok);
    FUZZ_REQUIRE(decode(*second.message) == value);

    if (options.sender == Sender::client && options.transport == wire::Transport::udp)
      (void)check_udp_sender(*verified.message, 42, cookie);
    if (const auto* frames = verified.message->body_as_FrameData()) check_frame_data(*frames);
  }
  return 0;
}
