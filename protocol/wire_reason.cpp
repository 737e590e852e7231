// Names of the reason codes, and the compile-time proof that Reason equals ocean.fbs's ErrorCode.
#include "wire_reason.hpp"

#include <cstddef>

namespace ocean::protocol {
namespace {

struct ReasonEntry {
  Reason reason;
  wire::ErrorCode code;  // the same-named value generated from ocean.fbs
  std::string_view name;
};

constexpr ReasonEntry kEntries[] = {
    {Reason::ok, wire::ErrorCode::ok, "ok"},
    {Reason::truncated, wire::ErrorCode::truncated, "truncated"},
    {Reason::oversized, wire::ErrorCode::oversized, "oversized"},
    {Reason::empty, wire::ErrorCode::empty, "empty"},
    {Reason::trailing_bytes, wire::ErrorCode::trailing_bytes, "trailing_bytes"},
    {Reason::bad_identifier, wire::ErrorCode::bad_identifier, "bad_identifier"},
    {Reason::bad_verifier, wire::ErrorCode::bad_verifier, "bad_verifier"},
    {Reason::misaligned_buffer, wire::ErrorCode::misaligned_buffer, "misaligned_buffer"},
    {Reason::unknown_version, wire::ErrorCode::unknown_version, "unknown_version"},
    {Reason::unknown_message_type, wire::ErrorCode::unknown_message_type, "unknown_message_type"},
    {Reason::unexpected_message, wire::ErrorCode::unexpected_message, "unexpected_message"},
    {Reason::missing_field, wire::ErrorCode::missing_field, "missing_field"},
    {Reason::unknown_profile, wire::ErrorCode::unknown_profile, "unknown_profile"},
    {Reason::bad_dimensions, wire::ErrorCode::bad_dimensions, "bad_dimensions"},
    {Reason::bad_sequence, wire::ErrorCode::bad_sequence, "bad_sequence"},
    {Reason::bad_chunk_index, wire::ErrorCode::bad_chunk_index, "bad_chunk_index"},
    {Reason::non_finite_value, wire::ErrorCode::non_finite_value, "non_finite_value"},
    {Reason::out_of_range, wire::ErrorCode::out_of_range, "out_of_range"},
    {Reason::bad_enum, wire::ErrorCode::bad_enum, "bad_enum"},
    {Reason::bad_string, wire::ErrorCode::bad_string, "bad_string"},
    {Reason::bad_cookie, wire::ErrorCode::bad_cookie, "bad_cookie"},
    {Reason::bad_session, wire::ErrorCode::bad_session, "bad_session"},
    {Reason::unpadded_udp_hello, wire::ErrorCode::unpadded_udp_hello, "unpadded_udp_hello"},
    {Reason::stale_tick, wire::ErrorCode::stale_tick, "stale_tick"},
    {Reason::profile_unavailable, wire::ErrorCode::profile_unavailable, "profile_unavailable"},
    {Reason::server_full, wire::ErrorCode::server_full, "server_full"},
    {Reason::unauthorized, wire::ErrorCode::unauthorized, "unauthorized"},
    {Reason::timeout, wire::ErrorCode::timeout, "timeout"},
    {Reason::internal_error, wire::ErrorCode::internal_error, "internal_error"},
    {Reason::rate_limited, wire::ErrorCode::rate_limited, "rate_limited"},
};

// Each row pairs a Reason with the schema value of the same name; both must sit at the row's
// index, so a schema edit that forgets this file (or the reverse) fails to build.
constexpr bool entries_match_schema() {
  constexpr std::size_t count = sizeof(kEntries) / sizeof(kEntries[0]);
  if (count != kReasonCount || static_cast<std::size_t>(wire::ErrorCode::MAX) + 1 != count) return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (static_cast<std::size_t>(kEntries[i].reason) != i) return false;
    if (static_cast<std::size_t>(kEntries[i].code) != i) return false;
  }
  return true;
}
static_assert(entries_match_schema(), "protocol::Reason and wire::ErrorCode (ocean.fbs) disagree");

}  // namespace

std::string_view to_string(Reason reason) {
  const auto i = static_cast<std::size_t>(reason);
  return i < kReasonCount ? kEntries[i].name : std::string_view("unknown_reason");
}

}  // namespace ocean::protocol
