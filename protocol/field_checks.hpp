// The meaning checks verify_message() runs after the FlatBuffers Verifier: one function per
// message body, each returning the first broken rule. Internal to ocean_protocol.
#pragma once

#include <cstddef>
#include <string_view>

#include "ocean_generated.h"
#include "verify_message.hpp"
#include "wire_reason.hpp"

namespace ocean::protocol::detail {

struct Problem {
  Reason reason = Reason::ok;
  std::string_view field;
  std::string_view rule;
  explicit operator bool() const { return reason != Reason::ok; }
};

// message has passed the Verifier and has a body of a known type; size is its byte count.
Problem check_body(const wire::Message& message, std::size_t size, wire::Transport transport);

}  // namespace ocean::protocol::detail
