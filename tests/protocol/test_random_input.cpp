// Random bytes and random mutations of valid messages: verify_message never crashes, never
// accepts noise, and whatever it accepts can be read in full and re-encoded.
#include <catch2/catch.hpp>

#include <random>

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "protocol_version.hpp"
#include "receiver.hpp"

using namespace ocean::protocol;
using namespace ocean::protocol::test;
namespace wire = ocean::wire;

namespace {

const VerifyOptions kAllOptions[] = {
    from(Sender::client, wire::Transport::tcp), from(Sender::server, wire::Transport::tcp),
    from(Sender::client, wire::Transport::udp), from(Sender::server, wire::Transport::udp)};

// An accepted message must be fully readable and survive another round trip.
void check_accepted(const Verified& v, const VerifyOptions& options) {
  REQUIRE(v.message != nullptr);
  const AnyMessage value = decode(*v.message);
  const Bytes again = encode(value);
  const Verified second = verify_message(again, options);
  INFO(describe(second));
  REQUIRE(second.ok);
  CHECK(decode(*second.message) == value);
}

}  // namespace

TEST_CASE("random buffers are rejected") {
  std::mt19937_64 rng(20261121);
  std::uniform_int_distribution<std::size_t> length(0, 1500);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int round = 0; round < 20000; ++round) {
    Bytes bytes(length(rng));
    for (auto& b : bytes) b = static_cast<std::uint8_t>(byte(rng));
    // Half the rounds get a correct size prefix and identifier so the Verifier itself is exercised.
    if (round % 2 == 0 && bytes.size() >= kMinMessageBytes) {
      const auto body = static_cast<std::uint32_t>(bytes.size() - 4);
      std::memcpy(bytes.data(), &body, 4);
      std::memcpy(bytes.data() + 8, kFileIdentifier, 4);
    }
    for (const VerifyOptions& options : kAllOptions) {
      const Verified v = verify_message(bytes, options);
      INFO("round " << round << ": " << describe(v));
      CHECK_FALSE(v.ok);
      CHECK(v.reason != Reason::ok);
    }
  }
}

TEST_CASE("mutated valid messages never crash and what passes is sound") {
  std::mt19937_64 rng(7);
  Receiver receiver = busy_receiver();
  std::size_t accepted = 0, rejected = 0, blocks_refused = 0;
  for (const Sample& sample : all_samples()) {
    const Bytes original = encode(sample.message);
    std::uniform_int_distribution<std::size_t> position(0, original.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> flips(1, 4);
    for (int round = 0; round < 1500; ++round) {
      Bytes mutated = original;
      for (int f = flips(rng); f > 0; --f) mutated[position(rng)] = static_cast<std::uint8_t>(byte(rng));
      for (const VerifyOptions& options : kAllOptions) {
        const Verified v = verify_message(mutated, options);
        if (v.ok) {
          ++accepted;
          check_accepted(v, options);
          // A FrameData whose block is broken passes the gate; the receiver then refuses the
          // block as a whole.
          Receiver fresh = receiver;
          if (fresh.receive(mutated, options) != Reason::ok) {
            ++blocks_refused;
            REQUIRE(fresh == receiver);
          }
        } else {
          ++rejected;
          const Receiver before = receiver;
          receiver.receive(mutated, options);
          REQUIRE(receiver == before);
        }
      }
    }
  }
  CHECK(rejected > accepted);  // most mutations break a rule
  CHECK(accepted > 0);         // and some only change a value, which is fine
  CHECK(blocks_refused > 0);   // some break a FrameData's block only
}
