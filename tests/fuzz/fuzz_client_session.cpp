// libFuzzer harness for ClientSession, the client's reader of network bytes: after a real Welcome
// it is fed arbitrary TCP messages and UDP datagrams (record_format.hpp; tag bit 0: UDP, bits 1-3:
// time step in 50 ms units, bit 4: run update() after). Mode byte bit 0: close on a bad TCP
// message as PROTOCOL.md says (else keep going, to reach deeper states).
// Invariants: everything the client sends verifies as a client message on its transport (UDP at
// most one datagram's size); a closed session stays closed and sends nothing more; a shown frame
// has grid^2 finite heights.
#include <cmath>
#include <cstdint>

#include "client_exchange.hpp"
#include "fuzz_check.hpp"
#include "record_format.hpp"
#include "verify_message.hpp"

using namespace ocean;

namespace {

void require_client_message(std::span<const std::uint8_t> bytes, wire::Transport transport) {
  const protocol::Bytes copy(bytes.begin(), bytes.end());
  const protocol::Verified v = protocol::verify_message(copy, {protocol::Sender::client, transport});
  FUZZ_REQUIRE(v.ok);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in({data, size});
  client::ClientSessionConfig config;
  config.close_on_bad_tcp_message = (in.take<std::uint8_t>() & 1) != 0;

  bool closed = false;
  std::size_t samples = 0;  // grid^2 once the Welcome is in
  client::ClientSessionEvents events;
  events.send_tcp = [&](std::span<const std::uint8_t> b) {
    FUZZ_REQUIRE(!closed);
    require_client_message(b, wire::Transport::tcp);
  };
  events.send_udp = [&](std::span<const std::uint8_t> b) {
    FUZZ_REQUIRE(!closed);
    FUZZ_REQUIRE(b.size() <= protocol::kMaxDatagram);
    require_client_message(b, wire::Transport::udp);
  };
  events.on_frame = [&](const codec::ReconstructedFrame& frame, std::uint32_t) {
    FUZZ_REQUIRE(samples == 0 || frame.height.size() == samples);
    for (float h : frame.height) FUZZ_REQUIRE(std::isfinite(h));
  };
  events.on_closed = [&](const std::string& why) {
    FUZZ_REQUIRE(!why.empty());
    closed = true;
  };
  client::ClientSession session(config, events);
  double now = 0.0;
  session.start(now);
  session.on_tcp_message(fuzz::real_welcome(), now);
  FUZZ_REQUIRE(session.state() == client::ClientSession::State::streaming);
  samples = std::size_t{session.welcome()->stream.grid} * session.welcome()->stream.grid;

  fuzz::Record record;
  for (int n = 0; n < 64 && fuzz::next_record(in, record); ++n) {
    now += 0.05 * ((record.tag >> 1) & 7);
    if (record.tag & 1) session.on_udp_datagram(record.bytes, now);
    else session.on_tcp_message(record.bytes, now);
    if (record.tag & 16) session.update(now);
    if (closed) FUZZ_REQUIRE(session.state() == client::ClientSession::State::closed);
    if (session.state() == client::ClientSession::State::closed) closed = true;
    if (const codec::Decoder* decoder = session.decoder())
      FUZZ_REQUIRE(std::size_t{decoder->config().grid} * decoder->config().grid == samples);
  }
  return 0;
}
