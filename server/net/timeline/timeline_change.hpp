// TimelineChange: one entry of the fleet's timeline log - an admin's accepted scene change or
// vessel command, stamped with its effective tick by the replica that took it - as the bytes
// TimelineLog stores. Its body is the SceneUpdate every replica will announce (PROTOCOL.md 6.2,
// serial left 0: each replica numbers scenes as it announces them), so a reader in any language
// that reads the wire reads the log; before it, the replica and the admin session that asked, so
// that one replica answers the admin when the entry comes back. Every read passes
// verify_message: a damaged entry is skipped alike by every replica, never half-applied.
// Pure: bytes in, bytes out.
#pragma once

#include "message_types.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace ocean::server {

struct TimelineChange {
  std::uint64_t origin = 0;   // the replica that took the change (random per process)
  std::uint64_t session = 0;  // the admin's session on that replica
  protocol::SceneUpdate update;  // request_id, effective_tick, the scene, the fleet when it changes
};

// "ocean-timeline 1\n", origin and session (8 bytes each, little-endian), then the SceneUpdate as
// a framed wire message.
std::string encode_change(const TimelineChange& change);
// nullopt with `error` naming what is wrong (an entry another version wrote, damaged bytes).
std::optional<TimelineChange> decode_change(const std::string& bytes, std::string& error);

}  // namespace ocean::server
