// The four link models of one simulated client (client::ConnectionLinks), built from its LinkSpec.
#pragma once

#include <cstdint>

#include "link_spec.hpp"
#include "packet_link.hpp"

namespace ocean::loadtest {

// Down: TCP and UDP queue behind one shared Bottleneck at the spec's rate (an access link has one
// downlink, whatever the transport); up likewise. Loss, jitter, reordering and duplication apply
// to UDP only. An unimpaired spec gives no links at all (sockets straight to the session).
// stream_only: the client has no UDP (--transport tcp or ws), so its stream carries every frame
// and the link's loss shows on it as TCP shows it, as retransmission delay (tcp_view).
client::ConnectionLinks make_client_links(const LinkSpec& spec, std::uint64_t seed, bool stream_only = false);

// What TCP sees of a link: its rate and delay, and a queue that never drops (a message that
// vanished would break the session, which no TCP does); with loss_as_delay, a message with a lost
// segment comes a retransmission timeout late, holding back those behind it.
LinkSpec tcp_view(const LinkSpec& spec, bool loss_as_delay = false);

}  // namespace ocean::loadtest
