// The four link models of one simulated client (client::ConnectionLinks), built from its LinkSpec.
#pragma once

#include <cstdint>

#include "link_spec.hpp"
#include "packet_link.hpp"

namespace ocean::loadtest {

// Down: TCP and UDP queue behind one shared Bottleneck at the spec's rate (an access link has one
// downlink, whatever the transport); up likewise. Loss, jitter, reordering and duplication apply
// to UDP only. An unimpaired spec gives no links at all (sockets straight to the session).
client::ConnectionLinks make_client_links(const LinkSpec& spec, std::uint64_t seed);

// What TCP sees of a link: its rate and delay, and a queue that never drops (TCP turns loss into
// retransmission delay; a message that vanished would break the session, which no TCP does).
LinkSpec tcp_view(const LinkSpec& spec);

}  // namespace ocean::loadtest
