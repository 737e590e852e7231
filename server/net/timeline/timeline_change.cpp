#include "timeline_change.hpp"

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "verify_message.hpp"

#include <string_view>
#include <vector>

namespace ocean::server {
namespace {

constexpr std::string_view kMagic = "ocean-timeline 1\n";
constexpr std::size_t kHeader = kMagic.size() + 16;

void put_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::uint64_t get_u64(const std::string& in, std::size_t at) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}

}  // namespace

std::string encode_change(const TimelineChange& change) {
  std::string out(kMagic);
  put_u64(out, change.origin);
  put_u64(out, change.session);
  protocol::SceneUpdate update = change.update;
  update.serial = 0;
  const protocol::Bytes message = protocol::encode(update);
  out.append(message.begin(), message.end());
  return out;
}

std::optional<TimelineChange> decode_change(const std::string& bytes, std::string& error) {
  if (bytes.size() < kHeader || std::string_view(bytes).substr(0, kMagic.size()) != kMagic) {
    error = "not an ocean-timeline 1 entry (another version wrote it, or it is damaged)";
    return std::nullopt;
  }
  // verify_message wants its bytes 8-byte aligned: a vector's storage is.
  const std::vector<std::uint8_t> message(bytes.begin() + static_cast<std::ptrdiff_t>(kHeader), bytes.end());
  protocol::VerifyOptions options;
  options.sender = protocol::Sender::server;
  options.max_message_bytes = std::max<std::size_t>(options.max_message_bytes, message.size());
  const protocol::Verified verified = protocol::verify_message(message, options);
  if (!verified) {
    error = "its SceneUpdate: " + protocol::describe(verified);
    return std::nullopt;
  }
  if (verified.message->body_type() != wire::Body::SceneUpdate) {
    error = "its message is not a SceneUpdate";
    return std::nullopt;
  }
  TimelineChange change;
  change.origin = get_u64(bytes, kMagic.size());
  change.session = get_u64(bytes, kMagic.size() + 8);
  change.update = protocol::read(*verified.message->body_as_SceneUpdate());
  return change;
}

}  // namespace ocean::server
