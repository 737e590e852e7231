// Reason: why a message was rejected or a request refused, one value per kind of failure.
// Values equal ocean.fbs's ErrorCode (checked at compile time) so a Reason goes on the wire as is;
// PROTOCOL.md ("Reason codes") repeats this table for other languages.
#pragma once

#include <cstdint>
#include <string_view>

#include "ocean_generated.h"

namespace ocean::protocol {

enum class Reason : std::uint8_t {
  ok = 0,
  // --- framing: raised by TcpFramer and verify_message before FlatBuffers looks at the bytes
  truncated = 1,          // fewer bytes than the size prefix announces, or than any message needs (12)
  oversized = 2,          // size above the limit: max_message_bytes on TCP, kMaxDatagram (1200) on UDP
  empty = 3,              // size prefix 0, or a zero-length datagram
  trailing_bytes = 4,     // a datagram holds more bytes than its size prefix announces
  bad_identifier = 5,     // bytes 8..11 are not the file identifier "OCNP"
  bad_verifier = 6,       // the FlatBuffers Verifier failed: offsets out of bounds, bad vtable, too deep
  misaligned_buffer = 7,  // receiver bug, never a peer's fault: the bytes do not start 8-byte aligned
  // --- envelope
  unknown_version = 8,       // Message.version != kProtocolVersion
  unknown_message_type = 9,  // body type NONE or newer than this version knows
  unexpected_message = 10,   // this message type may not come from this sender or on this transport
  missing_field = 11,        // a field the message needs is absent (e.g. Welcome without stream)
  // --- meaning of the fields
  unknown_profile = 12,   // a profile id not in protocol/profile.hpp (0 allowed only in Hello)
  bad_dimensions = 13,    // sizes disagree: grid vs profile, grid vs scene, a vector's length
  bad_sequence = 14,      // a frame record's tick offset beyond the block's newest tick, or its
                          // lag beyond kMaxFrameLag or its own tick
  bad_chunk_index = 15,   // a frame record's count 0 or > kMaxChunksPerFrame, or index >= count
  non_finite_value = 16,  // a float or double is NaN or infinite
  out_of_range = 17,      // a finite number outside its documented range (PROTOCOL.md names each)
  bad_enum = 18,          // an enum value this version does not define
  bad_string = 19,        // a string longer than its limit or not valid UTF-8
  bad_cookie = 20,        // UDP cookie missing, of a length outside 8..64, or not the session's
  bad_session = 21,       // session id 0 or not the receiver's session
  unpadded_udp_hello = 22,  // UdpHello smaller than kUdpHelloMinBytes (256): answering could amplify
  stale_tick = 23,        // version 1: a chunk of a frame already completed or too old (the codec's
                          // own stale_tick refusal covers this in version 2)
  // --- refusals a server sends in Error; verification never produces these
  profile_unavailable = 24,  // the wanted profile is valid but not offered by this server
  server_full = 25,          // no room for another session
  unauthorized = 26,         // ParamChange with a wrong admin token
  timeout = 27,              // the peer was silent longer than the server's idle limit
  internal_error = 28,       // the server failed; retrying later may help
  rate_limited = 29,         // a ParamChange beyond the admin rate (the text says when to retry)
};

inline constexpr std::uint8_t kReasonCount = 30;

// Stable snake_case name, e.g. "bad_chunk_index", for logs and metrics labels.
std::string_view to_string(Reason reason);

// Conversions to and from the wire enum; check is_known() before from_wire() on received codes
// (verify_message already rejects unknown ones with bad_enum).
inline wire::ErrorCode to_wire(Reason reason) { return static_cast<wire::ErrorCode>(reason); }
inline Reason from_wire(wire::ErrorCode code) { return static_cast<Reason>(code); }
inline bool is_known(wire::ErrorCode code) {
  return static_cast<std::uint8_t>(code) < kReasonCount;
}

}  // namespace ocean::protocol
