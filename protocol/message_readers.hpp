// decode(): a verified wire::Message -> its plain value (message_types.hpp). Only call these on
// a message that verify_message() accepted; they copy, so the value outlives the bytes.
// Hot paths may read the verified wire::Message directly instead (e.g. FrameData blocks).
#pragma once

#include "message_types.hpp"

namespace ocean::protocol {

AnyMessage decode(const wire::Message& message);

StreamParams read(const wire::StreamParams& stream);
SceneParams read(const wire::SceneParams& scene);
Hello read(const wire::Hello& message);
Welcome read(const wire::Welcome& message);
// A Welcome's vessel as a track (field_checks validates it as model::validate does).
model::VesselTrack read(const wire::Vessel& vessel);
UdpHello read(const wire::UdpHello& message);
UdpReady read(const wire::UdpReady& message);
Ack read(const wire::Ack& message);
KeyframeRequest read(const wire::KeyframeRequest& message);
SetTransport read(const wire::SetTransport& message);
ParamChange read(const wire::ParamChange& message);
SceneUpdate read(const wire::SceneUpdate& message);
Error read(const wire::Error& message);
Bye read(const wire::Bye& message);
Ping read(const wire::Ping& message);
Pong read(const wire::Pong& message);
FrameData read(const wire::FrameData& message);
HeightQuery read(const wire::HeightQuery& message);
HeightAnswer read(const wire::HeightAnswer& message);

}  // namespace ocean::protocol
