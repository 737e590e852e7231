// The protocol version and file identifier every message carries (PROTOCOL.md, "Versioning").
// Bump kProtocolVersion on any change a peer of the previous version could misread; appending fields does not.
#pragma once

#include <cstdint>

namespace ocean::protocol {

inline constexpr std::uint16_t kProtocolVersion = 4;

// The FlatBuffers file identifier of ocean.fbs; bytes 8..11 of every size-prefixed message.
inline constexpr char kFileIdentifier[] = "OCNP";

}  // namespace ocean::protocol
