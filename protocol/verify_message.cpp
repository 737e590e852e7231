// The receive gate: framing, identifier, FlatBuffers Verifier, envelope, then field meaning.
#include "verify_message.hpp"

#include <cstdint>

#include "field_checks.hpp"
#include "protocol_version.hpp"

namespace ocean::protocol {
namespace {

static_assert(kProtocolVersion < 10, "kVersionText below holds one digit");
constexpr char kVersionText[] = {static_cast<char>('0' + kProtocolVersion), '\0'};

Verified reject(Reason reason, std::string_view field, std::string_view rule) {
  Verified result;
  result.reason = reason;
  result.field = field;
  result.rule = rule;
  return result;
}

// Framing checks, before anything looks inside: the size prefix must describe exactly these bytes.
Verified check_frame(std::span<const std::uint8_t> bytes, std::size_t max_bytes) {
  if (bytes.empty()) return reject(Reason::empty, "message", "at least 12 bytes");
  if (reinterpret_cast<std::uintptr_t>(bytes.data()) % 8 != 0)
    return reject(Reason::misaligned_buffer, "message", "bytes starting at an 8-byte aligned address");
  if (bytes.size() > max_bytes) return reject(Reason::oversized, "message", "size <= the transport's limit");
  if (bytes.size() < kSizePrefixBytes) return reject(Reason::truncated, "size prefix", "4 bytes");
  const auto announced = flatbuffers::ReadScalar<std::uint32_t>(bytes.data());
  if (announced == 0) return reject(Reason::empty, "size prefix", "> 0");
  if (announced > bytes.size() - kSizePrefixBytes) return reject(Reason::truncated, "size prefix", "<= bytes received - 4");
  if (announced < bytes.size() - kSizePrefixBytes) return reject(Reason::trailing_bytes, "size prefix", "== bytes received - 4");
  if (bytes.size() < kMinMessageBytes) return reject(Reason::truncated, "message", "at least 12 bytes");
  if (!flatbuffers::BufferHasIdentifier(bytes.data() + kSizePrefixBytes, kFileIdentifier))
    return reject(Reason::bad_identifier, "file identifier", "\"OCNP\" at bytes 8..11");
  Verified ok;
  ok.ok = true;
  return ok;
}

}  // namespace

bool may_send(Sender sender, wire::Body type) {
  switch (type) {
    case wire::Body::Hello:
    case wire::Body::UdpHello:
    case wire::Body::Ack:
    case wire::Body::KeyframeRequest:
    case wire::Body::SetTransport:
    case wire::Body::ParamChange:
    case wire::Body::HeightQuery:
    case wire::Body::Ping:
      return sender == Sender::client;
    case wire::Body::Welcome:
    case wire::Body::UdpReady:
    case wire::Body::FrameData:
    case wire::Body::SceneUpdate:
    case wire::Body::Pong:
    case wire::Body::HeightAnswer:
      return sender == Sender::server;
    case wire::Body::Error:
    case wire::Body::Bye:
      return true;
    case wire::Body::FrameChunk:   // version 1 only
    case wire::Body::FrameBundle:  // version 1 only
    case wire::Body::NONE:
      break;
  }
  return false;
}

bool may_travel(wire::Transport transport, wire::Body type) {
  switch (type) {
    case wire::Body::UdpHello:
    case wire::Body::UdpReady:
      return transport == wire::Transport::udp;
    case wire::Body::Ack:
    case wire::Body::KeyframeRequest:
    case wire::Body::Ping:
    case wire::Body::Pong:
      return true;
    default:
      return transport == wire::Transport::tcp;
  }
}

Verified verify_message(std::span<const std::uint8_t> bytes, const VerifyOptions& options) {
  const bool udp = options.transport == wire::Transport::udp;
  const std::size_t max_bytes = udp ? kMaxDatagram : options.max_message_bytes;
  if (Verified frame = check_frame(bytes, max_bytes); !frame.ok) return frame;

  flatbuffers::Verifier verifier(bytes.data(), bytes.size(), kVerifierMaxDepth, kVerifierMaxTables);
  if (!wire::VerifySizePrefixedMessageBuffer(verifier))
    return reject(Reason::bad_verifier, "message", "a valid FlatBuffer of ocean.fbs");

  const wire::Message* message = wire::GetSizePrefixedMessage(bytes.data());
  if (message->version() != kProtocolVersion)
    return reject(Reason::unknown_version, "Message.version", kVersionText);
  const wire::Body type = message->body_type();
  if (type == wire::Body::NONE || static_cast<std::uint8_t>(type) > static_cast<std::uint8_t>(wire::Body::MAX))
    return reject(Reason::unknown_message_type, "Message.body_type", "a type defined in ocean.fbs");
  if (!may_send(options.sender, type))
    return reject(Reason::unexpected_message, wire::EnumNameBody(type), "a type this sender may send");
  if (!may_travel(options.transport, type))
    return reject(Reason::unexpected_message, wire::EnumNameBody(type), "a type allowed on this transport");
  if (detail::Problem problem = detail::check_body(*message, bytes.size(), options.transport))
    return reject(problem.reason, problem.field, problem.rule);

  Verified result;
  result.ok = true;
  result.message = message;
  return result;
}

std::string describe(const Verified& result) {
  std::string text(to_string(result.reason));
  if (result.ok) return text;
  text += " in ";
  text += result.field;
  text += ": expected ";
  text += result.rule;
  return text;
}

Reason check_udp_sender(const wire::Message& message, std::uint64_t session_id,
                        std::span<const std::uint8_t> cookie) {
  std::uint64_t carried_session = 0;
  const flatbuffers::Vector<std::uint8_t>* carried_cookie = nullptr;
  if (const auto* m = message.body_as_UdpHello()) {
    carried_session = m->session_id();
    carried_cookie = m->cookie();
  } else if (const auto* m = message.body_as_Ack()) {
    carried_session = m->session_id();
    carried_cookie = m->cookie();
  } else if (const auto* m = message.body_as_KeyframeRequest()) {
    carried_session = m->session_id();
    carried_cookie = m->cookie();
  } else if (const auto* m = message.body_as_Ping()) {
    carried_session = m->session_id();
    carried_cookie = m->cookie();
  } else {
    return Reason::unexpected_message;
  }
  if (carried_session != session_id) return Reason::bad_session;
  if (!carried_cookie || carried_cookie->size() != cookie.size() || cookie.empty()) return Reason::bad_cookie;
  std::uint8_t difference = 0;
  for (std::size_t i = 0; i < cookie.size(); ++i) difference |= carried_cookie->Get(i) ^ cookie[i];
  return difference == 0 ? Reason::ok : Reason::bad_cookie;
}

}  // namespace ocean::protocol
